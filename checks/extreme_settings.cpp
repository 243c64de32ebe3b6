// The extreme-settings grid: runs every test program headless across a
// covering set of world settings and checks that each run ends cleanly.
//
//   extreme_settings [--jobs N] [--timeout S] [--step-budget N] [--max-seconds S]
//                    [--work-dir DIR] [--only PROGRAM] [--strict-ode-errors] [--list] PROGRAM_PATH...
//
// Settings: step 1e-5, 1e-4, 1e-3, 1e-2, 0.1 s; ERP 0, 0.5, 1; CFM 0, 1e-3, 1;
// iterations 1, 20, 1000; solver quick, step. Their full product (270 per
// program) is too slow for CI, so each program gets a pairwise covering set
// (15 rows in which every value of every parameter meets every value of every
// other; checked below when the program starts) plus the extreme corners
// listed in CORNERS. A run lasts min(--max-seconds, --step-budget x step)
// simulated seconds (defaults 3 s and 10000 steps: 0.1 s at step 1e-5, 1 s
// at 1e-4, 3 s from 1e-3 up), so its cost is bounded in steps. Defaults:
// 2 jobs, a 120 s timeout per run.
//
// Each run's exit status is classified:
//   0  ok          the metrics JSON parses and says non_finite = 0
//   3  blew up     allowed: standard error names the blow-up and the very
//                  settings of the run, and the metrics say non_finite = 1
//   4  ODE error   allowed: a clean, named exit; its "error: ... ODE" message is printed
//                  (with --strict-ode-errors it must also name the run's settings)
//   anything else, a signal, or no end within --timeout (a hang): FAILED.
// A table lists every run; the status is 1 when any run FAILED.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iomanip>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "Metrics.h"

namespace {

const std::vector<double> STEPS{1e-5, 1e-4, 1e-3, 1e-2, 0.1};
const std::vector<double> ERPS{0.0, 0.5, 1.0};
const std::vector<double> CFMS{0.0, 1e-3, 1.0};
const std::vector<int> ITERATIONS{1, 20, 1000};
const std::vector<std::string> SOLVERS{"quick", "step"};

struct Settings {
  double step, erp, cfm;
  int iterations;
  std::string solver;
  std::string label;  // "pairwise" or what the corner stands for
};

// The corners that a pairwise set may miss: each end of the step range with
// the settings that stress it most.
const std::vector<Settings> CORNERS{
    {1e-5, 1.0, 0.0, 1000, "quick", "corner: smallest step, most iterations, rigid"},
    {1e-5, 0.0, 0.0, 1, "quick", "corner: smallest step, no correction, one iteration"},
    {1e-5, 0.0, 1.0, 20, "step", "corner: smallest step, softest, dWorldStep"},
    {0.1, 1.0, 0.0, 20, "quick", "corner: largest step, ERP 1, CFM 0"},
    {0.1, 1.0, 0.0, 20, "step", "corner: largest step, ERP 1, CFM 0, dWorldStep"},
    {0.1, 0.0, 0.0, 1, "quick", "corner: largest step, no correction, one iteration"},
    {0.1, 1.0, 1.0, 1000, "quick", "corner: largest step, softest, most iterations"},
    {0.1, 0.0, 1.0, 1, "step", "corner: largest step, softest, dWorldStep"},
};

// Rows (i, j), i over the 5 steps and j over the 3 ERPs: CFM (i+j) mod 3,
// iterations (j+2i) mod 3, solver (i+j) mod 2.
std::vector<Settings> pairwiseRows() {
  std::vector<Settings> rows;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j)
      rows.push_back({STEPS[i], ERPS[j], CFMS[(i + j) % 3], ITERATIONS[(j + 2 * i) % 3], SOLVERS[(i + j) % 2],
                      "pairwise"});
  return rows;
}

// True when every pair of values of every two parameters occurs in `rows`.
bool coversEveryPair(const std::vector<Settings>& rows) {
  auto levels = [](const Settings& s) {
    return std::vector<std::string>{std::to_string(s.step), std::to_string(s.erp), std::to_string(s.cfm),
                                    std::to_string(s.iterations), s.solver};
  };
  const std::vector<size_t> sizes{STEPS.size(), ERPS.size(), CFMS.size(), ITERATIONS.size(), SOLVERS.size()};
  for (size_t a = 0; a < sizes.size(); ++a)
    for (size_t b = a + 1; b < sizes.size(); ++b) {
      std::set<std::pair<std::string, std::string>> seen;
      for (const auto& row : rows) seen.insert({levels(row)[a], levels(row)[b]});
      if (seen.size() != sizes[a] * sizes[b]) return false;
    }
  return true;
}

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
  pid_t pid = -1;
  std::chrono::steady_clock::time_point started;
  double wall = 0;
  bool timedOut = false;
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

void start(Run& run, const std::string& workDir) {
  std::string pattern = workDir + "/" + run.name + "_XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (!mkdtemp(buffer.data())) {
    std::perror("extreme_settings: mkdtemp");
    std::exit(2);
  }
  run.dir = buffer.data();
  run.args.insert(run.args.end(), {"--out-dir", run.dir, "--metrics-json", run.dir + "/metrics.json"});
  run.started = std::chrono::steady_clock::now();
  run.pid = fork();
  if (run.pid == 0) {
    setpgid(0, 0);  // its own group, so a timeout kills everything it started
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
  if (run.timedOut) return fail("hang: no end within the timeout, killed");
  if (WIFSIGNALED(run.rawStatus))
    return fail(std::string("crash: signal ") + std::to_string(WTERMSIG(run.rawStatus)) + " (" +
                strsignal(WTERMSIG(run.rawStatus)) + ")");
  const int status = WEXITSTATUS(run.rawStatus);
  odelab::Metrics metrics;
  bool haveMetrics = false;
  try {
    const std::string json = readFile(run.dir + "/metrics.json");
    if (!json.empty()) {
      metrics = odelab::parseMetricsJson(json);
      haveMetrics = true;
    }
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

int usage() {
  std::cerr << "usage: extreme_settings [--jobs N] [--timeout S] [--step-budget N] [--max-seconds S]\n"
               "                        [--work-dir DIR] [--only PROGRAM] [--strict-ode-errors] [--list] PROGRAM_PATH...\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  int jobs = 2;
  double timeout = 120;
  double stepBudget = 10000;
  double maxSeconds = 3;
  std::string workDir = ".";
  std::set<std::string> only;
  bool listOnly = false;
  bool strictOdeErrors = false;
  std::vector<std::string> programs;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--jobs" && hasValue) jobs = std::atoi(argv[++i]);
    else if (arg == "--timeout" && hasValue) timeout = std::atof(argv[++i]);
    else if (arg == "--step-budget" && hasValue) stepBudget = std::atof(argv[++i]);
    else if (arg == "--max-seconds" && hasValue) maxSeconds = std::atof(argv[++i]);
    else if (arg == "--work-dir" && hasValue) workDir = argv[++i];
    else if (arg == "--only" && hasValue) only.insert(argv[++i]);
    else if (arg == "--list") listOnly = true;
    else if (arg == "--strict-ode-errors") strictOdeErrors = true;
    else if (arg.rfind("--", 0) == 0) return usage();
    else programs.push_back(arg);
  }
  if (programs.empty() || jobs < 1 || !(timeout > 0) || !(stepBudget >= 1) || !(maxSeconds > 0)) return usage();

  const std::vector<Settings> pairwise = pairwiseRows();
  if (!coversEveryPair(pairwise)) {
    std::cerr << "extreme_settings: the pairwise rows do not cover every pair of values\n";
    return 2;
  }
  std::vector<Settings> cases = pairwise;
  for (const auto& corner : CORNERS) {
    bool present = false;
    for (auto& c : cases)
      if (c.step == corner.step && c.erp == corner.erp && c.cfm == corner.cfm && c.iterations == corner.iterations &&
          c.solver == corner.solver) {
        c.label = corner.label;
        present = true;
      }
    if (!present) cases.push_back(corner);
  }

  std::deque<Run> queue;
  for (const auto& program : programs) {
    const std::string name = baseName(program);
    if (!only.empty() && !only.count(name)) continue;
    for (const auto& s : cases) {
      Run run;
      run.program = program;
      run.name = name;
      run.settings = s;
      run.seconds = std::min(maxSeconds, stepBudget * s.step);
      run.args = {"--headless",   "--seconds", number(run.seconds), "--step",   number(s.step),
                  "--erp",        number(s.erp), "--cfm",           number(s.cfm), "--iterations",
                  std::to_string(s.iterations), "--solver", s.solver};
      for (auto& a : sceneArgs(name, run.seconds)) run.args.push_back(a);
      queue.push_back(run);
    }
  }
  if (listOnly) {
    for (const auto& run : queue) std::cout << commandLine(run) << "    # " << run.settings.label << '\n';
    return 0;
  }
  std::cout << "extreme settings: " << queue.size() << " runs (" << cases.size() << " settings x "
            << queue.size() / std::max<size_t>(1, cases.size()) << " programs: " << pairwise.size()
            << " pairwise + " << cases.size() - pairwise.size() << " corners), " << jobs << " at a time, "
            << "each min(" << number(maxSeconds) << " s, " << number(stepBudget) << " steps), timeout "
            << number(timeout) << " s\n";

  const auto gridStart = std::chrono::steady_clock::now();
  std::vector<Run> done;
  std::vector<Run> running;
  while (!queue.empty() || !running.empty()) {
    while (static_cast<int>(running.size()) < jobs && !queue.empty()) {
      running.push_back(queue.front());
      queue.pop_front();
      start(running.back(), workDir);
    }
    bool finishedOne = false;
    for (size_t k = 0; k < running.size();) {
      Run& run = running[k];
      int status = 0;
      const pid_t got = waitpid(run.pid, &status, WNOHANG);
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - run.started).count();
      if (got == 0 && elapsed > timeout) {
        kill(-run.pid, SIGKILL);
        kill(run.pid, SIGKILL);
        waitpid(run.pid, &status, 0);
        run.timedOut = true;
      } else if (got == 0) {
        ++k;
        continue;
      }
      run.rawStatus = status;
      run.wall = elapsed;
      classify(run, strictOdeErrors);
      if (!run.failed) removeTree(run.dir);
      done.push_back(run);
      running.erase(running.begin() + static_cast<long>(k));
      finishedOne = true;
    }
    if (!finishedOne) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const double gridWall = std::chrono::duration<double>(std::chrono::steady_clock::now() - gridStart).count();

  // The table, in program order, then the summary.
  std::cout << std::left << std::setw(7) << "program" << ' ' << std::setw(7) << "step" << ' ' << std::setw(4) << "ERP"
            << ' ' << std::setw(6) << "CFM" << ' ' << std::setw(5) << "iter" << ' ' << std::setw(6) << "solver" << ' '
            << std::setw(6) << "sim s" << ' ' << std::setw(7) << "wall s" << ' ' << std::setw(10) << "result"
            << " detail\n";
  std::map<std::string, std::map<std::string, int>> counts;
  std::vector<std::string> programOrder;
  for (const auto& program : programs) programOrder.push_back(baseName(program));
  int failures = 0;
  for (const auto& name : programOrder)
    for (const auto& run : done) {
      if (run.name != name) continue;
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
      ++counts[run.name][run.result];
      failures += run.failed ? 1 : 0;
    }
  std::cout << "\nsummary (runs per program):\n"
            << std::left << std::setw(8) << "program" << std::setw(5) << "ok" << std::setw(9) << "blew up"
            << std::setw(11) << "ODE error" << "FAILED\n";
  for (const auto& name : programOrder) {
    if (!counts.count(name)) continue;
    auto& c = counts[name];
    std::cout << std::setw(8) << name << std::setw(5) << c["ok"] << std::setw(9) << c["blew up"] << std::setw(11)
              << c["ODE error"] << c["FAILED"] << '\n';
  }
  std::cout << std::fixed << std::setprecision(1) << done.size() << " runs in " << gridWall << " s wall; "
            << failures << " FAILED\n";
  return failures ? 1 : 0;
}
