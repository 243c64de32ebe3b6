// Runs test programs headless at extreme world settings (the grid of
// checks/extreme_grid.h) and checks that each run ends cleanly:
//
//   extreme_settings [--batch K --batches B] [--step-budget N] [--max-seconds S]
//                    [--work-dir DIR] [--strict-ode-errors] [--list] PROGRAM_PATH...
//
// Batch K of B is every grid setting whose index i has i mod B = K, for
// every PROGRAM_PATH (default: batch 0 of 1, the whole grid). The runs go one
// after another: checks/hardening.cmake registers one CTest row per program
// and batch, so `ctest -j` runs them side by side and each row's TIMEOUT
// catches a hang (a run's process dies with this one, see start()). A run
// lasts min(--max-seconds, --step-budget x step) simulated seconds (defaults
// 3 s and 10000 steps: 0.1 s at step 1e-5, 1 s at 1e-4, 3 s from 1e-3 up),
// so its cost is bounded in steps.
//
// Each run's exit status is classified:
//   0  ok          the metrics JSON parses and says non_finite = 0
//   3  blew up     allowed: standard error names the blow-up and the very
//                  settings of the run, and the metrics say non_finite = 1
//   4  ODE error   allowed: a clean, named exit; its "error: ... ODE" message is printed
//                  (with --strict-ode-errors it must also name the run's settings)
//   anything else, or a signal: FAILED.
// A table lists every run; the status is 1 when any run FAILED, 2 on bad
// input (an empty batch too: the grid has fewer settings than B).
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iomanip>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "check_cli.h"
#include "extreme_grid.h"
#include "metrics_file.h"

namespace {

using extreme::Settings;

std::string number(double value) {
  std::ostringstream out;
  out << std::setprecision(6) << value;
  return out.str();
}

std::string baseName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

struct Run {
  std::string program;  // path
  std::string name;     // test0 ...
  Settings settings;
  double seconds = 0;
  std::vector<std::string> args;
  std::string dir;
  double wall = 0;
  int rawStatus = 0;
  // results
  std::string result;  // ok, blew up, ODE error, FAILED
  std::string detail;
  bool failed = false;
};

// What each scene needs so that a short run exercises it: test0 and test5
// spawn on a timer, test7 throws on a timer and test10 launches (both ignore
// --seconds otherwise).
std::vector<std::string> sceneArgs(const std::string& name, double seconds) {
  if (name == "test0") return {"--spawn-interval", number(seconds / 10)};
  if (name == "test5") return {"--spawn-interval", number(seconds / 10), "--plates", "10"};
  if (name == "test7") return {"--throws", "2", "--throw-interval", number(seconds / 2)};
  if (name == "test10") return {"--launches", "1"};
  return {};
}

std::string commandLine(const Run& run) {
  std::string text = run.program;
  for (const auto& a : run.args) text += " " + a;
  return text;
}

// Runs it to its end in a folder of its own under workDir, standard output
// and error into files there.
void runToEnd(Run& run, const std::string& workDir) {
  std::string pattern = workDir + "/" + run.name + "_XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (!mkdtemp(buffer.data())) {
    std::perror("extreme_settings: mkdtemp");
    std::exit(2);
  }
  run.dir = buffer.data();
  run.args.insert(run.args.end(), {"--out-dir", run.dir, "--metrics-json", run.dir + "/metrics.json"});
  const auto started = std::chrono::steady_clock::now();
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) {
#ifdef __linux__
    // CTest ends a row past its TIMEOUT by killing this process only; the
    // run must not go on spinning without it.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);  // already gone before the line above
#endif
    const int out = open((run.dir + "/stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open((run.dir + "/stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out, STDOUT_FILENO);
    dup2(err, STDERR_FILENO);
    std::vector<char*> argv{const_cast<char*>(run.program.c_str())};
    for (auto& a : run.args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    std::perror(argv[0]);
    _exit(127);
  }
  (void)parent;
  if (pid < 0) {
    std::perror("extreme_settings: fork");
    std::exit(2);
  }
  waitpid(pid, &run.rawStatus, 0);
  run.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The first line that contains every one of `needles`.
std::string firstLineWith(const std::string& text, std::initializer_list<const char*> needles) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    bool all = true;
    for (const char* needle : needles) all = all && line.find(needle) != std::string::npos;
    if (all) return line;
  }
  return {};
}

bool near(double a, double b) { return std::fabs(a - b) <= 1e-5 * std::max(1.0, std::fabs(b)); }

// The blow-up message must name the settings the run was given.
bool namesSettings(const std::string& line, const Settings& s) {
  static const std::regex pattern(
      R"(step ([^,]+), ERP ([^,]+), CFM ([^,]+), solver (\w+), (\d+) iterations)");
  std::smatch m;
  if (!std::regex_search(line, m, pattern)) return false;
  return near(std::atof(m[1].str().c_str()), s.step) && near(std::atof(m[2].str().c_str()), s.erp) &&
         near(std::atof(m[3].str().c_str()), s.cfm) && m[4].str() == s.solver &&
         std::atoi(m[5].str().c_str()) == s.iterations;
}

void classify(Run& run, bool strictOdeErrors) {
  const std::string err = readFile(run.dir + "/stderr.txt");
  auto fail = [&](const std::string& why) {
    run.result = "FAILED";
    run.failed = true;
    run.detail = why;
  };
  if (WIFSIGNALED(run.rawStatus))
    return fail(std::string("crash: signal ") + std::to_string(WTERMSIG(run.rawStatus)) + " (" +
                strsignal(WTERMSIG(run.rawStatus)) + ")");
  const int status = WEXITSTATUS(run.rawStatus);
  odelab::Metrics metrics;
  bool haveMetrics = false;
  try {  // none, an empty file or a malformed one: no metrics
    metrics = checks::readMetricsFile(run.dir + "/metrics.json");
    haveMetrics = true;
  } catch (const std::exception&) {
  }
  if (status == 0) {
    if (!haveMetrics) return fail("exit 0 but no readable metrics JSON");
    if (metrics.get("non_finite") != 0) return fail("exit 0 but non_finite = " + number(metrics.get("non_finite")));
    run.result = "ok";
    run.detail = "t=" + number(metrics.get("sim_seconds")) + " s, " + number(metrics.get("bodies")) + " bodies";
    return;
  }
  if (status == 3) {
    const std::string line = firstLineWith(err, {"simulation blew up"});
    if (line.empty()) return fail("exit 3 without a 'simulation blew up' message");
    if (!namesSettings(line, run.settings)) return fail("exit 3, but the message does not name the run's settings: " + line);
    if (!haveMetrics || metrics.get("non_finite") != 1) return fail("exit 3, but the metrics do not say non_finite = 1");
    run.result = "blew up";
    run.detail = line;
    return;
  }
  if (status == 4) {
    const std::string line = firstLineWith(err, {"error: ", "ODE"});
    if (line.empty()) return fail("exit 4 without an 'error: ... ODE' message");
    if (strictOdeErrors && !namesSettings(line, run.settings))
      return fail("exit 4, but the message does not name the run's settings: " + line);
    run.result = "ODE error";
    run.detail = line;
    return;
  }
  std::string first = firstLineWith(err, {});
  fail("exit " + std::to_string(status) + (first.empty() ? "" : ": " + first));
}

void removeTree(const std::string& dir) {
  for (const char* name : {"stdout.txt", "stderr.txt", "metrics.json", "Test2_output.txt", "Test8_output.txt"})
    std::remove((dir + "/" + name).c_str());
  // A run cut short can leave the metrics' temporary file, .metrics.json.XXXXXX.
  std::error_code ignored;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ignored))
    if (entry.path().filename().string().rfind(".metrics.json.", 0) == 0) std::filesystem::remove(entry.path(), ignored);
  rmdir(dir.c_str());
}

void printTable(const std::vector<Run>& done) {
  std::cout << std::left << std::setw(7) << "program" << ' ' << std::setw(7) << "step" << ' ' << std::setw(4) << "ERP"
            << ' ' << std::setw(6) << "CFM" << ' ' << std::setw(5) << "iter" << ' ' << std::setw(6) << "solver" << ' '
            << std::setw(6) << "sim s" << ' ' << std::setw(7) << "wall s" << ' ' << std::setw(10) << "result"
            << " detail\n";
  for (const auto& run : done) {
    const Settings& s = run.settings;
    std::ostringstream wall;
    wall << std::fixed << std::setprecision(2) << run.wall;
    std::cout << std::left << std::setw(7) << run.name << ' ' << std::setw(7) << number(s.step) << ' '
              << std::setw(4) << number(s.erp) << ' ' << std::setw(6) << number(s.cfm) << ' ' << std::setw(5)
              << s.iterations << ' ' << std::setw(6) << s.solver << ' ' << std::setw(6) << number(run.seconds)
              << ' ' << std::setw(7) << wall.str() << ' ' << std::setw(10) << run.result << ' ' << run.detail;
    if (s.label != "pairwise") std::cout << "  [" << s.label << "]";
    std::cout << '\n';
    if (run.result != "ok") std::cout << "        replay: " << commandLine(run) << '\n';
    if (run.failed) std::cout << "        kept for inspection: " << run.dir << '\n';
  }
}

void printSummary(const std::vector<Run>& done, double gridWall) {
  std::map<std::string, std::map<std::string, int>> counts;
  std::vector<std::string> order;
  int failures = 0;
  for (const auto& run : done) {
    if (!counts.count(run.name)) order.push_back(run.name);
    ++counts[run.name][run.result];
    failures += run.failed ? 1 : 0;
  }
  std::cout << "\nsummary (runs per program):\n"
            << std::left << std::setw(8) << "program" << std::setw(5) << "ok" << std::setw(9) << "blew up"
            << std::setw(11) << "ODE error" << "FAILED\n";
  for (const auto& name : order) {
    auto& c = counts[name];
    std::cout << std::setw(8) << name << std::setw(5) << c["ok"] << std::setw(9) << c["blew up"] << std::setw(11)
              << c["ODE error"] << c["FAILED"] << '\n';
  }
  std::cout << std::fixed << std::setprecision(1) << done.size() << " runs in " << gridWall << " s wall; "
            << failures << " FAILED\n";
}

}  // namespace

int main(int argc, char** argv) {
  int batch = 0;
  int batches = 1;
  double stepBudget = 10000;
  double maxSeconds = 3;
  std::string workDir = ".";
  bool listOnly = false;
  bool strictOdeErrors = false;
  std::vector<std::string> programs;
  CLI::App app{"Runs test programs headless at extreme ERP, CFM, step, iterations and solver settings (a pairwise "
               "covering set plus corners) and checks that every run ends cleanly: 0, or a named blow-up (3) or "
               "ODE error (4).",
               "extreme_settings"};
  app.add_option("--batch", batch, "run batch K: the grid settings whose index i has i mod B = K")
      ->transform(checks::decimal())
      ->check(CLI::NonNegativeNumber);
  app.add_option("--batches", batches, "split the grid's settings into B batches")
      ->transform(checks::decimal())
      ->check(CLI::PositiveNumber);
  app.add_option("--step-budget", stepBudget, "a run's most steps: it lasts min(--max-seconds, N x step)")
      ->check(CLI::Range(1.0, 1e12));
  app.add_option("--max-seconds", maxSeconds, "a run's most simulated seconds")
      ->check(CLI::PositiveNumber);
  app.add_option("--work-dir", workDir, "each run's folder goes here (kept when the run FAILED)")
      ->check(CLI::ExistingDirectory);
  app.add_flag("--strict-ode-errors", strictOdeErrors, "an ODE error (exit 4) must also name the run's settings");
  app.add_flag("--list", listOnly, "print the batch's command lines and exit");
  app.add_option("programs", programs, "the test programs to run (their file names say which scene)")->required();
  if (auto status = checks::parse(app, argc, argv, [&] {
        if (batch >= batches)
          throw CLI::ValidationError("--batch", std::to_string(batch) + " is not below --batches " +
                                                    std::to_string(batches));
      }))
    return *status;

  std::vector<Settings> cases;
  try {
    cases = extreme::gridSettings();
  } catch (const std::logic_error& error) {
    std::cerr << "extreme_settings: " << error.what() << '\n';
    return 2;
  }
  std::vector<size_t> chosen;
  for (size_t i = static_cast<size_t>(batch); i < cases.size(); i += static_cast<size_t>(batches)) chosen.push_back(i);
  if (chosen.empty()) {
    // A batch with nothing to run would pass while checking nothing.
    std::cerr << "extreme_settings: error: batch " << batch << " of " << batches << " holds no setting: the grid has "
              << cases.size() << " (set the batches in checks/hardening.cmake to at most that)\n";
    return 2;
  }

  std::vector<Run> runs;
  for (const auto& program : programs)
    for (size_t index : chosen) {
      Run run;
      run.program = program;
      run.name = baseName(program);
      run.settings = cases[index];
      const Settings& s = run.settings;
      run.seconds = std::min(maxSeconds, stepBudget * s.step);
      run.args = {"--headless",   "--seconds", number(run.seconds), "--step",   number(s.step),
                  "--erp",        number(s.erp), "--cfm",           number(s.cfm), "--iterations",
                  std::to_string(s.iterations), "--solver", s.solver};
      for (auto& a : sceneArgs(run.name, run.seconds)) run.args.push_back(a);
      runs.push_back(run);
    }
  if (listOnly) {
    for (const auto& run : runs) std::cout << commandLine(run) << "    # " << run.settings.label << '\n';
    return 0;
  }
  std::cout << "extreme settings: " << runs.size() << " runs (" << chosen.size() << " of the grid's " << cases.size()
            << " settings, batch " << batch << " of " << batches << ", x " << programs.size()
            << " programs), each min(" << number(maxSeconds) << " s, " << number(stepBudget) << " steps)\n";

  const auto gridStart = std::chrono::steady_clock::now();
  int failures = 0;
  for (auto& run : runs) {
    runToEnd(run, workDir);
    classify(run, strictOdeErrors);
    if (!run.failed) removeTree(run.dir);
    failures += run.failed ? 1 : 0;
  }
  const double gridWall = std::chrono::duration<double>(std::chrono::steady_clock::now() - gridStart).count();
  printTable(runs);
  printSummary(runs, gridWall);
  return failures ? 1 : 0;
}
