#include "TimeControl.h"

#include <algorithm>

namespace odelab {

namespace {
// The HUD's recent figures average over about this much real time.
constexpr double RECENT_SECONDS = 1.0;
// Drawing limits the rate when busy time fills this share of the period.
constexpr double BUSY_SHARE = 0.9;
}  // namespace

const char* frameLimitName(FrameLimit limit) {
  switch (limit) {
    case FrameLimit::Pacing: return "paced";
    case FrameLimit::Drawing: return "drawing";
    case FrameLimit::Physics: return "physics";
  }
  return "?";
}

void TimeControl::slower() { scale_ = std::max(MIN_SCALE, scale_ * 0.5); }

void TimeControl::faster() { scale_ = std::min(MAX_SCALE, scale_ * 2.0); }

int TimeControl::stepsFor(double elapsedSeconds, double step) {
  return paused_ ? 0 : clock_.advance(elapsedSeconds, step, scale_);
}

void TimeControl::dropSteps(long long count) {
  droppedSteps_ += count;
  windowDropped_ += count;
  clock_.reset();  // carried over, they would only make the next frame late too
}

void TimeControl::endFrame(double elapsedSeconds, double simulatedSeconds, double steppingSeconds,
                           double busySeconds, double periodSeconds) {
  ++frames_;
  wall_ += elapsedSeconds;
  // A paused frame is not a frame that failed to keep up.
  if (!paused_) {
    runningWall_ += elapsedSeconds;
    simulated_ += simulatedSeconds;
  }
  longestFrame_ = std::max(longestFrame_, elapsedSeconds);
  ++windowFrames_;
  windowReal_ += elapsedSeconds;
  windowSim_ += simulatedSeconds;
  windowBusy_ += busySeconds;
  windowStepping_ += steppingSeconds;
  windowPeriod_ += periodSeconds;
  if (windowReal_ < RECENT_SECONDS) return;
  recentFps_ = windowFrames_ / windowReal_;
  recentFactor_ = windowSim_ / windowReal_;
  // Busy frames are limited by whichever of stepping and drawing took more.
  const bool busy = windowBusy_ >= BUSY_SHARE * windowPeriod_;
  if (windowDropped_ > 0 || (busy && 2 * windowStepping_ > windowBusy_))
    limit_ = FrameLimit::Physics;
  else if (busy)
    limit_ = FrameLimit::Drawing;
  else
    limit_ = FrameLimit::Pacing;
  windowFrames_ = windowDropped_ = 0;
  windowReal_ = windowSim_ = windowBusy_ = windowStepping_ = windowPeriod_ = 0.0;
}

void TimeControl::addRun(double wallSeconds, double simulatedSeconds) {
  wall_ += wallSeconds;
  runningWall_ += wallSeconds;
  simulated_ += simulatedSeconds;
}

}  // namespace odelab
