#pragma once

#include <string>
#include <vector>

#include "AbstractWindow.h"

namespace odelab {

// The compare window's physics (doc/manual.md, "Engines side by side"): ODE's
// scene, the one the window runs, leads; every other engine's scene follows
// it step for step. What a person does to ODE's scene (keys, the panel, a
// drag, R) reaches every other scene before the step it came before
// (AbstractWindow::echoInputs), and after each frame follow() brings every
// other scene to ODE's step: forward by stepping, back (a rewind) by its own
// replay. So each engine runs the run its own `--engine` window would,
// given the same inputs at the same steps. It never calls GL.
class CompareLanes {
 public:
  struct Lane {
    AbstractWindow* scene = nullptr;
    std::string engine;   // "ode", "bullet", ...
    std::string version;  // its version ("" where unknown), read once
    // Why this engine stopped following (a blow-up, a non-finite state, an
    // ODE error), and the step it failed on; "" while it follows.
    std::string failure;
    long long failedAt = -1;
    // Wall milliseconds a step of this engine takes (its scene's stepOnce,
    // measurement included), smoothed over the last frames that stepped.
    double msPerStep = 0.0;
    double steppingSeconds = 0.0;  // wall time of all its steps (follow())
  };

  // `lead` is ODE's scene; `others` each another engine's, built from the
  // same command line (CompareRun), in the order named.
  CompareLanes(AbstractWindow& lead, const std::vector<std::pair<std::string, AbstractWindow*>>& others);
  ~CompareLanes();
  CompareLanes(const CompareLanes&) = delete;
  CompareLanes& operator=(const CompareLanes&) = delete;

  // After the lead's frame: every other scene to the lead's step.
  // `leadSeconds` is the wall time the lead's own steps took in that frame.
  void follow(double leadSeconds, long long leadSteps);
  // Every lane, the lead's first.
  const std::vector<Lane>& lanes() const { return lanes_; }
  // The viewport's label: "bullet 3.24 default   2 notes" and, under it, the
  // scene's headline measurement on that engine (or why it stopped).
  std::vector<std::string> label(const Lane& lane) const;
  // How many steps every lane together takes within `seconds` of wall time
  // (from their smoothed times per step; at least 1, 0 while none is
  // known): the most steps a frame's share of a rewind may replay.
  long long stepsWithin(double seconds) const;
  // The longest time one input took to reach every other engine (R builds
  // each engine's world again there), seconds; 0 before any input.
  double longestInputSeconds() const { return longestInputSeconds_; }
  // The HUD's line: each engine's time per step and, when the window falls
  // behind real time, the engine that takes the longest.
  std::string timingLine() const;
  // The same for `lanes` as given, and whether the window is behind real
  // time (then the slowest engine is named first).
  static std::string timingLine(const std::vector<Lane>& lanes, bool behindRealTime);

 private:
  void stop(Lane& lane, const std::string& why);

  std::vector<Lane> lanes_;
  double longestInputSeconds_ = 0.0;
};

}  // namespace odelab
