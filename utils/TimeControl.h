#pragma once

#include "FixedStepClock.h"

namespace odelab {

// What holds a window's frame rate down, for the HUD.
enum class FrameLimit {
  Pacing,   // the frame cap or vsync: the machine has time to spare
  Drawing,  // drawing a frame takes longer than the frame period
  Physics,  // the frame's steps overran the stepping budget (some dropped)
};
const char* frameLimitName(FrameLimit limit);  // "paced", "drawing", "physics"

// Real time against simulated time in a window: pause and time scale, the
// fixed-step clock, the per-frame stepping budget, and the figures a window
// run reports (frame rate, real-time factor, longest frame, dropped steps).
// Headless runs use none of it but the run totals. No ODE, no GL.
class TimeControl {
 public:
  // A frame's steps may take this much real time; what is left of them is
  // dropped, so that whatever the settings (step 1e-5 at 8x with 1000
  // iterations asks for 8000 costly steps a frame) the window goes on
  // answering input. The simulation then runs slower than real time, which
  // the HUD's real-time factor shows; dropped_steps counts them.
  static constexpr double STEPPING_BUDGET = 0.05;
  static constexpr double MIN_SCALE = 1.0 / 32.0;
  static constexpr double MAX_SCALE = 8.0;

  // ---- pause and time scale (P, -, =) ----
  bool paused() const { return paused_; }
  void setPaused(bool paused) { paused_ = paused; }
  double scale() const { return scale_; }
  void slower();  // halves, down to MIN_SCALE
  void faster();  // doubles, up to MAX_SCALE

  // ---- the clock ----
  void setMaximumFrameTime(double seconds) { clock_.setMaximumElapsedTime(seconds); }
  double maximumFrameTime() const { return clock_.maximumElapsedTime(); }
  // The steps this frame's real time asks for (none while paused).
  int stepsFor(double elapsedSeconds, double step);
  // The steps of this frame from `index` on did not fit the budget.
  void dropSteps(long long count);
  void resetClock() { clock_.reset(); }

  // ---- accounting, once a frame ----
  // `busySeconds` is the part of the frame spent stepping and drawing,
  // `steppingSeconds` the part spent stepping; `simulatedSeconds` how far
  // the simulation advanced; `periodSeconds` the frame period the pacing
  // aims at (0 when unpaced).
  void endFrame(double elapsedSeconds, double simulatedSeconds, double steppingSeconds, double busySeconds,
                double periodSeconds);
  // Headless: a stretch of stepping with no frames.
  void addRun(double wallSeconds, double simulatedSeconds);

  long long frames() const { return frames_; }
  long long droppedSteps() const { return droppedSteps_; }
  double longestFrameSeconds() const { return longestFrame_; }
  // Over the whole session (every reset included; the real-time factor
  // leaves paused frames out).
  double sessionWallSeconds() const { return wall_; }
  double sessionRealTimeFactor() const { return runningWall_ > 0 ? simulated_ / runningWall_ : 0.0; }
  double sessionFramesPerSecond() const { return wall_ > 0 ? frames_ / wall_ : 0.0; }
  // Over roughly the last second of frames, for the HUD.
  double recentRealTimeFactor() const { return recentFactor_; }
  double recentFramesPerSecond() const { return recentFps_; }
  FrameLimit limit() const { return limit_; }

 private:
  FixedStepClock clock_;
  bool paused_ = false;
  double scale_ = 1.0;
  long long frames_ = 0;
  long long droppedSteps_ = 0;
  double longestFrame_ = 0.0;
  double wall_ = 0.0, runningWall_ = 0.0, simulated_ = 0.0;
  // The window the recent figures average over.
  long long windowFrames_ = 0, windowDropped_ = 0;
  double windowReal_ = 0.0, windowSim_ = 0.0, windowBusy_ = 0.0, windowStepping_ = 0.0, windowPeriod_ = 0.0;
  double recentFactor_ = 0.0, recentFps_ = 0.0;
  FrameLimit limit_ = FrameLimit::Pacing;
};

}  // namespace odelab
