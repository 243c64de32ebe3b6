#include "RunLog.h"

#include <exception>

#include "LineText.h"
#include "MeasurementLog.h"

namespace odelab {

std::string RunLog::write(double simulatedTime, long long step, const std::string& text) {
  if (failed_ || path_.empty()) return {};
  try {
    if (!file_.isOpen()) {
      file_.open(path_);
      file_.write("# " + lineText(title_) + ": inputs that changed the simulation, with their simulated time\n");
    }
    // Flushed entry by entry: a crash keeps every input made before it.
    file_.write(timeStamp(simulatedTime) + " (step " + std::to_string(step) + "): " + lineText(text) + "\n");
  } catch (const std::exception& error) {
    failed_ = true;
    return std::string("the run log is not kept: ") + error.what();
  }
  return {};
}

}  // namespace odelab
