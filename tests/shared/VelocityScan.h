#pragma once

#include <algorithm>
#include <functional>
#include <ostream>
#include <string>

#include "FormatValue.h"
#include "Metrics.h"

namespace odelab {

// The upward velocity scan of test10 --find-max-velocity: every 1 m/s up to
// 1000 m/s, then every 0.1%, to the highest velocity V such that every
// launch at every tested velocity up to V was stopped. Since that needs
// every launch up to V, the limit is settled at the first failing velocity;
// the scan goes on through a band above it (to bandFactor x the first
// failure) only to show whether stops come back there.
class VelocityScan {
 public:
  static constexpr double FINE_STEP = 1.0;       // m/s
  static constexpr double FINE_LIMIT = 1000.0;   // m/s: every 1 m/s below this
  static constexpr double COARSE_RATIO = 0.001;  // every 0.1% above

  // What one tested velocity gave.
  // Slowed: a cube lost speed before it reached the wall (an engine's speed
  // cap): the wall was not what was tested, so the scan ends there.
  enum class Trial { AllStopped, SomePassed, BlewUp, Slowed };

  struct Result {
    double maxVelocity = 0.0;
    double maxVelocityResolution = 0.0;
    double firstFailure = 0.0;  // 0: none up to the scan limit
    double bandUpper = 0.0;
    int stoppedInBand = 0;
    int passedInBand = 0;
    double highestStoppedInBand = 0.0;
    int tested = 0;
    bool blewUp = false;
    double firstSlowed = 0.0;  // the velocity a launch first lost speed before the wall at; 0: none
  };

  VelocityScan(double limit, double bandFactor) : limit_(limit), bandFactor_(bandFactor) {}

  static double next(double velocity) {
    return velocity < FINE_LIMIT ? velocity + FINE_STEP : velocity * (1.0 + COARSE_RATIO);
  }
  static double resolutionAt(double velocity) { return velocity < FINE_LIMIT ? FINE_STEP : velocity * COARSE_RATIO; }

  // Tests velocities upward with `trial` (it launches at one velocity and
  // says what happened) until the band above the first failure, the scan
  // limit or a blow-up ends it.
  Result run(const std::function<Trial(double velocity)>& trial) const {
    Result r;
    for (double v = FINE_STEP; v <= limit_ * (1 + 1e-12); v = next(v)) {
      if (r.firstFailure > 0.0 && v > r.bandUpper) break;
      const Trial outcome = trial(v);
      if (outcome == Trial::BlewUp) {
        r.blewUp = true;
        break;
      }
      if (outcome == Trial::Slowed) {
        r.firstSlowed = v;
        break;
      }
      ++r.tested;
      const bool stopped = outcome == Trial::AllStopped;
      if (r.firstFailure == 0.0) {
        if (stopped) {
          r.maxVelocity = v;
          continue;
        }
        r.firstFailure = v;
        r.bandUpper = std::min(limit_, v * bandFactor_);
      } else if (stopped) {
        ++r.stoppedInBand;
        r.highestStoppedInBand = v;
      } else {
        ++r.passedInBand;
      }
    }
    r.maxVelocityResolution = resolutionAt(r.maxVelocity);
    return r;
  }

  // The scan's result as lines: `what` says how each velocity was tested.
  void print(const Result& r, const std::string& what, std::ostream& out) const {
    out << "scan: every 1 m/s up to 1000 m/s, every 0.1% above; " << what << '\n';
    if (r.blewUp) out << "scan: stopped early, the simulation blew up\n";
    if (r.firstSlowed > 0.0)
      out << "scan: stopped at " << formatValue(r.firstSlowed)
          << " m/s: a cube lost speed before it reached the wall (the engine caps speeds); no wall limit above it\n";
    if (r.firstFailure == 0.0) {
      out << "scan: no launch passed up to the scan limit " << formatValue(limit_) << " m/s\n";
      return;
    }
    out << "max velocity " << formatValue(r.maxVelocity) << " m/s (resolution " << formatValue(r.maxVelocityResolution)
        << " m/s): every launch up to it was stopped; first launch through at " << formatValue(r.firstFailure)
        << " m/s\n";
    out << "band " << formatValue(r.firstFailure) << " - " << formatValue(r.bandUpper) << " m/s: " << r.stoppedInBand
        << " tested velocities stopped again, " << r.passedInBand << " passed"
        << (r.stoppedInBand ? " (highest stopped " + formatValue(r.highestStoppedInBand) + " m/s)" : "") << '\n';
  }

  static void addMetrics(const Result& r, Metrics& m) {
    m.set("max_velocity", r.maxVelocity);
    m.set("max_velocity_resolution", r.maxVelocityResolution);
    m.set("first_failure_velocity", r.firstFailure);
    m.set("band_upper_velocity", r.bandUpper);
    m.set("velocities_stopped_in_band", r.stoppedInBand);
    m.set("velocities_passed_in_band", r.passedInBand);
    m.set("highest_stopped_velocity_in_band", r.highestStoppedInBand);
    m.set("tested_velocities", r.tested);
    m.set("first_slowed_velocity", r.firstSlowed);
  }

 private:
  double limit_;
  double bandFactor_;
};

}  // namespace odelab
