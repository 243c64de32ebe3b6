#include "DragEnergy.h"

#include <algorithm>

namespace odelab {

void DragEnergy::pulled(double energy, const double force[3], const double point[3]) {
  if (!began_) before_ = energy;
  began_ = true;
  for (int k = 0; k < 3; ++k) {
    force_[k] = force[k];
    point_[k] = point[k];
  }
}

void DragEnergy::moved(const double point[3]) {
  for (int k = 0; k < 3; ++k) work_ += force_[k] * (point[k] - point_[k]);
}

void DragEnergy::released(double energy) {
  if (!began_) return;
  afterMax_ = afterRelease_ ? std::max(afterMax_, energy) : energy;
  afterRelease_ = true;
}

void DragEnergy::write(Metrics& metrics) const {
  if (!afterRelease_) return;
  metrics.set("drag_energy_before_J", before_);
  metrics.set("drag_work_J", work_);
  metrics.set("drag_energy_after_release_max_J", afterMax_);
  metrics.set("drag_energy_excess_J", afterMax_ - (before_ + work_));
}

}  // namespace odelab
