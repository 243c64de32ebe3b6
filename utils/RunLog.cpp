#include "RunLog.h"

#include <cerrno>
#include <cstring>
#include <exception>

#include "MeasurementLog.h"
#include "SafeFile.h"

namespace odelab {

RunLog::~RunLog() {
  if (file_) std::fclose(file_);
}

std::string RunLog::fail(const std::string& why) {
  failed_ = true;
  if (file_) std::fclose(file_);
  file_ = nullptr;
  return "cannot write the run log '" + path_ + "': " + why;
}

std::string RunLog::write(double simulatedTime, long long step, const std::string& text) {
  if (failed_ || path_.empty()) return {};
  if (!file_) {
    try {
      file_ = openExclusiveOutput(path_);
    } catch (const std::exception& error) {
      failed_ = true;
      return std::string("the run log is not kept: ") + error.what();
    }
    std::fprintf(file_, "# %s: inputs that changed the simulation, with their simulated time\n", title_.c_str());
  }
  // Flushed entry by entry: a crash keeps every input made before it.
  if (std::fprintf(file_, "%s (step %lld): %s\n", timeStamp(simulatedTime).c_str(), step, text.c_str()) < 0 ||
      std::fflush(file_) != 0)
    return fail(std::strerror(errno));
  return {};
}

}  // namespace odelab
