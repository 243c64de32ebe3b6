#pragma once

#include <string>
#include <vector>

#include "Metrics.h"

namespace odelab {

// The metrics of a window session that switched scenes (odelab's Page Down /
// Page Up): every scene visit keeps its own figures, taken as it closes, so
// that marks made before a switch stay, and each figure names its scene.
// A visit's metric NAME is written "visit<N>.<scene>.NAME" (N from 1, in
// the order shown: "visit1.test2.energy_start_J", "visit3.test2.mark_a_steps"),
// and "visits" counts them. A session that never switched has one visit and
// writes its metrics as a program of its own does, names unchanged.
// Every metric of `from` (numbers and lists of sentences) into `into`, its
// name after `prefix`: "visit1.test2." here, "bullet." in a compare run
// (utils/CompareRun.h).
void addPrefixed(Metrics& into, const std::string& prefix, const Metrics& from);

class SceneVisits {
 public:
  // A visit that has ended: `scene` is its program's name ("test2").
  void add(const std::string& scene, const Metrics& metrics);
  // The session's metrics, the scene still on screen (`scene`, `last`) the last visit.
  Metrics session(const std::string& scene, const Metrics& last) const;
  size_t ended() const { return visits_.size(); }

 private:
  struct Visit {
    std::string scene;
    Metrics metrics;
  };
  std::vector<Visit> visits_;
};

}  // namespace odelab
