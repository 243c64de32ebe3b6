#pragma once

#include <string>
#include <utility>

#include "StreamedFile.h"

namespace odelab {

// The window session's record of inputs that changed the simulation
// (<test>_run_log.txt in --out-dir). Opened on the first entry, so a session
// with no input leaves no file; closes itself. A failure to open or
// write is reported once and the session goes on without a log.
class RunLog {
 public:
  void setTarget(std::string path, std::string title) {
    path_ = std::move(path);
    title_ = std::move(title);
  }
  // Appends "t=<time> s (step <n>): text". Returns an error message the
  // first time the file cannot be opened or written, else "".
  std::string write(double simulatedTime, long long step, const std::string& text);

 private:
  std::string path_, title_;
  StreamedFile file_;  // the one writer of streamed outputs
  bool failed_ = false;
};

}  // namespace odelab
