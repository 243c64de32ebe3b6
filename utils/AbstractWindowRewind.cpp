// AbstractWindow, rewind: ',' rebuilds the world at the run's start and
// replays the recorded inputs up to a snapshot. A long run takes many steps
// to replay (and a compare window replays every engine), so the replay is
// spread over frames: the window keeps drawing, the HUD says how far it has
// come, Esc or any input that changes the run stops it where it is, and
// further presses of ',' only move the target back.
#include <chrono>
#include <string>

#include "AbstractWindow.h"
#include "MeasurementLog.h"
#include "OdeMessages.h"

namespace odelab {

void AbstractWindow::beginReplay() {
  session_.dragEnergy_.clear();  // the energy books were of the run left behind
  session_.rewind_.setReplaying(true);
  const RunStart& start = session_.rewind_.restore();
  tuning_.settings_ = start.settings;
  run_.spaceKind_ = start.space;
  tuning_.increment_ = start.increment;
  run_.destroy();
  createWorld();
  session_.rewind_.timeline().rewindCursor();
}

void AbstractWindow::rewindTo(long long step, const std::string& leftAt) {
  session_.time_.setPaused(true);
  if (!rewindJob_.active) rewindJob_.leftAt = leftAt;
  // Already replayed past the new target: start the replay again.
  if (!rewindJob_.active || run_.steps_ > step) beginReplay();
  rewindJob_.active = true;
  rewindJob_.target = step;
}

void AbstractWindow::continueRewind(double budgetSeconds) {
  const auto start = std::chrono::steady_clock::now();
  long long done = 0;
  while (run_.steps_ < rewindJob_.target) {
    if (rewindJob_.stepsPerFrame > 0 && done >= rewindJob_.stepsPerFrame) return;
    if (done > 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > budgetSeconds)
      return;
    std::string failure;
    try {
      if (!stepOnce()) failure = run_.blowUpReason_;
    } catch (const OdeError& error) {
      run_.stepThreading_ = nullptr;  // see advanceFrame()
      failure = std::string("ODE error: ") + error.what();
    }
    if (!failure.empty()) {
      // The run that was recorded did not fail here; this replay did.
      endRewind(rewindJob_.leftAt + ": rewind stopped: " + failure);
      return;
    }
    ++done;
  }
  endRewind(rewindJob_.leftAt + ": rewound to " + timeStamp(run_.simulatedTime_));
}

void AbstractWindow::endRewind(const std::string& notice) {
  rewindJob_.active = false;
  session_.rewind_.setReplaying(false);
  session_.time_.setPaused(true);
  notify(notice);
  const std::string caveat = rewindCaveat();
  if (!caveat.empty()) notify("warning: " + caveat);
}

void AbstractWindow::cancelRewind() {
  if (!rewindJob_.active) return;
  endRewind(rewindJob_.leftAt + ": rewind stopped at " + timeStamp(run_.simulatedTime_) + " (step " +
            std::to_string(run_.steps_) + " of " + std::to_string(rewindJob_.target) + ")");
}

std::string AbstractWindow::rewindLine() const {
  if (!rewindJob_.active) return {};
  return "rewinding... (" + std::to_string(run_.steps_) + " of " + std::to_string(rewindJob_.target) +
         " steps; Esc stops)";
}

}  // namespace odelab
