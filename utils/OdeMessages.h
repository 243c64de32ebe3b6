#pragma once

#include <deque>
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

  // The latest messages (newest last, at most 4) of the last few seconds.
  static std::deque<std::string> recent();
  static long suppressedCount();
  static void clear();

  // Exposed for tests: the handler ODE calls for dMessage.
  static void handleMessage(int number, const std::string& text);
};

}  // namespace odelab
