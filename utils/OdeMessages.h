#pragma once

#include <deque>
#include <functional>
#include <stdexcept>
#include <string>

namespace odelab {

// Thrown from ODE's error and debug handlers: ODE would otherwise abort the
// process. The runner catches it and exits with exit_code::ODE_ERROR.
class OdeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Routes ODE's error, debug and message handlers. Messages (ODE's warnings,
// e.g. "LCP internal error") go to stderr at most a few per second, the rest
// counted and summarised, and the latest are kept for the HUD.
class OdeMessages {
 public:
  static void install();
  // The thread that steps a world now takes the main thread's part: ODE's
  // errors there are thrown as OdeError. A compare run (utils/CompareRun.cpp)
  // steps each engine's scene on a thread of its own, one at a time, and
  // calls this as each takes its turn, and on the main thread afterwards.
  static void adoptThread();

  // The latest messages (newest last, at most 4) of the last few seconds.
  static std::deque<std::string> recent();
  static long suppressedCount();
  static void clear();

  // What the run adds to an error raised in one of ODE's pool threads, where
  // no exception can carry it to the main thread: `moment` gives the time
  // and settings (" at t=... s (step ...)"), `markOutputs` ends the output
  // files as cut short, before the process ends. Both are called on the
  // failing pool thread while the main thread waits inside the step.
  // Empty functions (the default) add nothing.
  static void setRunContext(std::function<std::string()> moment, std::function<void(const std::string&)> markOutputs);

  // Exposed for tests: the handler ODE calls for dMessage.
  static void handleMessage(int number, const std::string& text);
};

}  // namespace odelab
