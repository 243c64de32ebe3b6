#pragma once

// Finds the apexes (local maxima of height) of a bouncing body from its
// position after each step; used by test1 (Jumping Balls) and test9
// (Restitution accuracy). Header-only so both programs share it without a
// CMake change.

#include <ode/ode.h>

namespace odelab {

struct Apex {
  double time;         // s
  double position[3];  // m, at the apex
};

class ApexTracker {
 public:
  // minimumRise: an apex must stand this far above the lowest point since the
  // previous apex, so that contact jitter of a ball at rest does not count.
  ApexTracker() = default;
  explicit ApexTracker(double minimumRise) : minimumRise_(minimumRise) {}

  void restart(double time, const dReal* position) {
    for (auto& sample : samples_) sample = Sample{time, {position[0], position[1], position[2]}};
    filled_ = 1;
    lowest_ = position[1];
    count_ = 0;
    releaseApex_ = Apex{time, {position[0], position[1], position[2]}};
  }

  // Feed the position after a step. True when the previous sample was a
  // local maximum of height; `apex` then holds the top of the parabola
  // through the last three samples. In free flight ODE's integrator puts the
  // samples exactly on a parabola (constant acceleration), so the vertex is
  // the apex between steps, not the highest step.
  bool update(double time, const dReal* position, Apex& apex) {
    samples_[0] = samples_[1];
    samples_[1] = samples_[2];
    samples_[2] = Sample{time, {position[0], position[1], position[2]}};
    if (filled_ < 3 && ++filled_ == 3) releaseApex_ = vertex();
    const double before = samples_[0].p[1], top = samples_[1].p[1], after = samples_[2].p[1];
    lowest_ = before < lowest_ ? before : lowest_;
    if (filled_ < 3 || !(top > before && top >= after) || top - lowest_ < minimumRise_) return false;
    apex = vertex();
    lowest_ = top;
    ++count_;
    return true;
  }

  int count() const { return count_; }

  // The apex of the flight the body was released into, found the same way:
  // the vertex of the parabola through the first three samples (valid once
  // two steps have run, and if nothing touched the body in them). For a body
  // released at rest from height y0 it is y0 + g h^2 / 8, half a step before
  // the release: in ODE's integrator (v += g h, then x += v h) the release
  // sample is not the top of its own parabola. Apexes compared with this
  // reference carry no such offset.
  const Apex& releaseApex() const { return releaseApex_; }

 private:
  struct Sample {
    double t;
    double p[3];
  };

  // Vertex of the parabola through the three samples (equal time spacing
  // assumed: a step size change between them only shifts the estimate within
  // a step); x and z are interpolated to the same instant.
  Apex vertex() const {
    const double curvature = samples_[0].p[1] - 2 * samples_[1].p[1] + samples_[2].p[1];  // < 0 at a maximum
    const double slope = 0.5 * (samples_[2].p[1] - samples_[0].p[1]);
    const double u = curvature < 0 ? -slope / curvature : 0.0;  // in steps from the middle sample, within [-0.5, 0.5]
    Apex apex;
    apex.time = samples_[1].t + u * (samples_[2].t - samples_[0].t) / 2;
    for (int i = 0; i < 3; ++i) {
      const double a = 0.5 * (samples_[0].p[i] - 2 * samples_[1].p[i] + samples_[2].p[i]);
      const double b = 0.5 * (samples_[2].p[i] - samples_[0].p[i]);
      apex.position[i] = samples_[1].p[i] + b * u + a * u * u;
    }
    return apex;
  }

  double minimumRise_ = 1e-6;  // m
  Sample samples_[3]{};
  int filled_ = 0;
  double lowest_ = 0.0;
  int count_ = 0;
  Apex releaseApex_{};
};

}  // namespace odelab
