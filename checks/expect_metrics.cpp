// Runs one test program and checks its metrics against stated bounds, so
// every CTest scene check reads as a physical claim:
//
//   expect_metrics [--status N] [--stdout-contains TEXT]... NAME<OP>BOUND ... -- PROGRAM ARGS...
//
// OP is one of < <= > >= ==. BOUND is a number, or another metric of the
// same run written @NAME, optionally with one arithmetic step: @NAME+2,
// @NAME-0.5, @NAME*1.1 (e.g. mark_b_steps==@mark_a_steps,
// mark_d_steps==@mark_c_steps+1, drag_end_distance<@drag_start_distance*0.5).
// The program gets "--metrics-json FILE" appended (headless runs and window
// runs both write it at exit, so a window run under Xvfb with --events is
// checked the same way) and must exit with status 0, or with the --status
// given (then the check is that the program failed with exactly that status;
// for status 2, a refused option, it also checks that no metrics file was
// written). Every measured value is printed beside its bound.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "Metrics.h"
#include "check_cli.h"
#include "metrics_file.h"

namespace {

struct Expectation {
  std::string name, op;
  double bound = 0.0;
  // A bound taken from another metric: bound = metric <arithmetic> operand.
  std::string boundMetric;
  char arithmetic = 0;  // 0, '+', '-' or '*'
  double operand = 0.0;
};

bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool parseNumber(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end && *end == '\0';
}

bool parseExpectation(const std::string& text, Expectation& e) {
  static const char* ops[] = {"<=", ">=", "==", "<", ">"};
  for (const char* op : ops) {
    const auto at = text.find(op);
    if (at == std::string::npos || at == 0) continue;
    e.name = text.substr(0, at);
    e.op = op;
    const std::string bound = text.substr(at + std::string(op).size());
    if (bound.empty() || bound[0] != '@') return parseNumber(bound, e.bound);
    std::size_t end = 1;
    while (end < bound.size() && isNameChar(bound[end])) ++end;
    e.boundMetric = bound.substr(1, end - 1);
    if (e.boundMetric.empty()) return false;
    if (end == bound.size()) return true;
    e.arithmetic = bound[end];
    if (e.arithmetic != '+' && e.arithmetic != '-' && e.arithmetic != '*') return false;
    return parseNumber(bound.substr(end + 1), e.operand);
  }
  return false;
}

// Resolves a bound that names another metric; false if that one is missing.
bool resolveBound(const odelab::Metrics& metrics, Expectation& e) {
  if (e.boundMetric.empty()) return true;
  if (!metrics.has(e.boundMetric)) return false;
  const double base = metrics.get(e.boundMetric);
  switch (e.arithmetic) {
    case '+': e.bound = base + e.operand; break;
    case '-': e.bound = base - e.operand; break;
    case '*': e.bound = base * e.operand; break;
    default: e.bound = base; break;
  }
  return true;
}

std::string describeBound(const Expectation& e) {
  std::ostringstream text;
  text << std::setprecision(16) << e.op << ' ' << e.bound;
  if (!e.boundMetric.empty()) {
    text << " = " << e.boundMetric;
    if (e.arithmetic) text << e.arithmetic << e.operand;
  }
  return text.str();
}

bool holds(double v, const Expectation& e) {
  if (e.op == "<") return v < e.bound;
  if (e.op == "<=") return v <= e.bound;
  if (e.op == ">") return v > e.bound;
  if (e.op == ">=") return v >= e.bound;
  return v == e.bound;
}

int runProgram(const std::vector<std::string>& args, std::string& output) {
  int pipeFds[2];
  if (pipe(pipeFds) != 0) return -1;
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(pipeFds[1], STDOUT_FILENO);
    close(pipeFds[0]);
    close(pipeFds[1]);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    std::perror(argv[0]);
    _exit(127);
  }
  close(pipeFds[1]);
  char buffer[4096];
  ssize_t n;
  while ((n = read(pipeFds[0], buffer, sizeof buffer)) > 0) {
    output.append(buffer, static_cast<size_t>(n));
    std::cout.write(buffer, n);
  }
  close(pipeFds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

int main(int argc, char** argv) {
  // Everything after the first "--" is the program's own command line,
  // passed on untouched: CLI11 reads only what comes before it.
  int separator = 1;
  while (separator < argc && std::string(argv[separator]) != "--") ++separator;
  std::vector<std::string> program(argv + std::min(separator + 1, argc), argv + argc);

  std::vector<std::string> texts;
  std::vector<std::string> mustContain;
  int expectedStatus = 0;
  CLI::App app{"Runs PROGRAM ARGS... with --metrics-json FILE appended and checks its exit status and metrics "
               "against NAME<OP>BOUND expectations (OP: < <= > >= ==; BOUND: a number or @NAME, optionally "
               "followed by +N, -N or *N).",
               "expect_metrics"};
  app.footer("The command line ends with -- PROGRAM ARGS...: everything after -- is the program's own.");
  app.add_option("--status", expectedStatus, "the exit status the program must end with (default 0)")
      ->transform(checks::decimal())
      ->check(CLI::Range(0, 255));
  app.add_option("--stdout-contains", mustContain, "text the program's standard output must contain")
      ->allow_extra_args(false);  // one TEXT each time, as before: what follows is an expectation
  app.add_option("expectations", texts, "NAME<OP>BOUND, e.g. steps>0 or mark_b_steps==@mark_a_steps+1");
  std::vector<Expectation> expectations;
  std::vector<char*> ours(argv, argv + separator);
  if (auto status = checks::parse(app, static_cast<int>(ours.size()), ours.data(), [&] {
        for (const auto& text : texts) {
          Expectation e;
          if (!parseExpectation(text, e)) throw CLI::ValidationError("cannot read expectation '" + text + "'");
          expectations.push_back(e);
        }
        if (program.empty()) throw CLI::ValidationError("no program after --");
      }))
    return *status;

  const std::string json = "expect_metrics_" + std::to_string(getpid()) + ".json";
  std::remove(json.c_str());
  program.push_back("--metrics-json");
  program.push_back(json);
  std::string output;
  const int status = runProgram(program, output);
  bool ok = true;
  if (status != expectedStatus) {
    std::cout << "FAIL: exit status " << status << ", expected " << expectedStatus << '\n';
    ok = false;
  }
  for (const auto& text : mustContain)
    if (output.find(text) == std::string::npos) {
      std::cout << "FAIL: output lacks '" << text << "'\n";
      ok = false;
    }
  const bool written = std::ifstream(json).good();
  if (expectedStatus == 2) {
    // A usage error must leave nothing behind.
    if (written) {
      std::cout << "FAIL: a metrics file was written although the options were refused\n";
      ok = false;
    }
  } else if (!written) {
    if (!expectations.empty()) {
      std::cout << "FAIL: no metrics file written\n";
      ok = false;
    }
  } else {
    try {
      const odelab::Metrics metrics = checks::readMetricsFile(json);
      for (auto e : expectations) {
        if (!resolveBound(metrics, e)) {
          std::cout << "FAIL: " << e.name << ": the bound's metric " << e.boundMetric << " was not reported\n";
          ok = false;
          continue;
        }
        if (!metrics.has(e.name)) {
          std::cout << "FAIL: " << e.name << " was not reported (expected " << describeBound(e) << ")\n";
          ok = false;
          continue;
        }
        const double v = metrics.get(e.name);
        const bool pass = holds(v, e);
        std::cout << (pass ? "ok:   " : "FAIL: ") << e.name << " = " << std::setprecision(16) << v << " (expected "
                  << describeBound(e) << ")\n";
        ok = ok && pass;
      }
    } catch (const std::exception& error) {
      std::cout << "FAIL: " << error.what() << '\n';
      ok = false;
    }
  }
  std::remove(json.c_str());
  return ok ? 0 : 1;
}
