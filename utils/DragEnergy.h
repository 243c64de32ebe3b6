#pragma once

#include "Metrics.h"

namespace odelab {

// The energy books of the mouse drag: what the bodies had when the first
// drag began, the work the drag spring did, and the most they had at any
// step after a release. A drag may put energy in (the spring's work) but a
// released body must not gain more: the excess
//   drag_energy_excess_J = max energy after release - (energy before + work)
// is what an engine made up (a force or torque that outlived its step, an
// impulse applied twice). The work is measured on the grabbed point's path:
// the force of each step times how far the point moved in that step, which
// covers the force's torque about the centre of mass too.
class DragEnergy {
 public:
  // Before a step in which the spring pulls: the bodies' energy, the force
  // and the grabbed point where it acts (world frame).
  void pulled(double energy, const double force[3], const double point[3]);
  // After that step: where the grabbed point went.
  void moved(const double point[3]);
  // After a step without a drag: the bodies' energy.
  void released(double energy);
  // Whether the energy after a step is wanted (a drag has begun).
  bool watching() const { return began_; }
  void clear() { *this = DragEnergy{}; }
  // drag_energy_before_J, drag_work_J, drag_energy_after_release_max_J and
  // drag_energy_excess_J, once a drag has been released.
  void write(Metrics& metrics) const;

 private:
  bool began_ = false;
  bool afterRelease_ = false;
  double before_ = 0.0;
  double work_ = 0.0;
  double afterMax_ = 0.0;
  double force_[3] = {0, 0, 0};
  double point_[3] = {0, 0, 0};
};

}  // namespace odelab
