// test10 - Maximum velocity (thesis 5.11): small cubes are launched at a thin
// vertical wall. ODE tests collisions only at the start of each step (no
// continuous collision detection), so a fast enough cube jumps over the wall
// or lands past its middle and is pushed out of the far side. The test finds
// the highest launch velocity at which every cube is still stopped.
//
// Measures: whether each launch passed through (its centre ends beyond the
// wall's far face); with --find-max-velocity, the highest velocity V such
// that every launch at every tested velocity up to V was stopped, tested every
// 1 m/s up to 1000 m/s and every 0.1% above.
//
// Geometry of the limit: a cube of half-size h crossing a wall of thickness t
// overlaps it while its centre lies within h + t/2 of the wall's mid-plane.
// At the first step that overlaps, the box-box test pushes the cube out along
// the axis of least penetration: back if its centre is still short of the
// mid-plane, forward (through) if it is past it. So every arrival is stopped
// while one step's travel v*step is below h + t/2; above that it depends on
// where the cube happens to be at the steps around the wall (the phase), which
// for a fixed launch point is a fixed function of v.
#include <CLI/CLI.hpp>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "AbstractWindow.h"
#include "Box.h"
#include "CommandLine.h"
#include "Plane.h"
#include "TestMain.h"

namespace {

using namespace odelab;

// The wall: thickness from the thesis; position and size (proposed).
constexpr double WALL_THICKNESS = 0.05;
constexpr double WALL_X = 0.0;       // centre of the wall (proposed)
constexpr double WALL_HEIGHT = 6.0;  // standing on the ground (proposed)
constexpr double WALL_WIDTH = 6.0;   // along z (proposed)
constexpr double WALL_NEAR_FACE = WALL_X - WALL_THICKNESS / 2;
constexpr double WALL_FAR_FACE = WALL_X + WALL_THICKNESS / 2;

// The launched cube, from the thesis.
constexpr double CUBE_SIDE = 0.4;
constexpr double CUBE_HALF = CUBE_SIDE / 2;
constexpr double CUBE_MASS = 1.0;
constexpr double LAUNCH_X = -4.0, LAUNCH_Y = 3.0, LAUNCH_Z = 0.0;

// World settings from the thesis: they limit how deep a cube may sink into the wall.
constexpr double ERP = 0.3;
constexpr double CFM = 0.0;
constexpr double SURFACE_LAYER = 0.0;

constexpr double DEFAULT_VELOCITY = 200.0;  // m/s (proposed): stopped at the default step
// F5 changes the velocity by 10 m/s below 1000 m/s and by 100 m/s from there up.
constexpr double F5_FINE_STEP = 10.0, F5_COARSE_STEP = 100.0, F5_COARSE_FROM = 1000.0;

// The scan of --find-max-velocity: every 1 m/s up to 1000 m/s, then every 0.1%.
constexpr double SCAN_FINE_STEP = 1.0;
constexpr double SCAN_FINE_LIMIT = 1000.0;
constexpr double SCAN_COARSE_RATIO = 0.001;
constexpr double DEFAULT_SCAN_LIMIT = 100000.0;  // m/s: where the scan gives up (proposed)
constexpr double DEFAULT_BAND_FACTOR = 1.5;      // keep scanning to 1.5x the first failure (proposed)

// A launch is over when the cube is wholly past the wall, or moves no longer
// toward it on the near side; failing both, after the time it needs to reach
// the wall plus this much (a soft contact, with CFM > 0, may take a while).
constexpr double SETTLE_SECONDS = 0.05;
// The window keeps launched cubes to show where they ended; farther away they go.
constexpr double KEEP_RADIUS = 100.0;

enum class Outcome { InFlight, Stopped, Passed };

const char* outcomeName(Outcome outcome) {
  switch (outcome) {
    case Outcome::InFlight:
      return "in flight";
    case Outcome::Stopped:
      return "stopped";
    case Outcome::Passed:
      return "passed through";
  }
  return "?";
}

std::string format(double value, int precision = 6) {
  std::ostringstream out;
  out << std::setprecision(precision) << value;
  return out.str();
}

struct Launch {
  Box* cube;
  double velocity;
  double launchedAt;
  Outcome outcome = Outcome::InFlight;
};

class MaximumVelocity : public AbstractWindow {
 public:
  MaximumVelocity() : AbstractWindow("test10 - Maximum velocity", settingsForThisScene()) {
    bindKey(SDLK_b, "B", "launch a cube from [-4, 3, 0] toward the wall at the launch velocity",
            [this](int) { launch(velocity_); });
    bindKey(SDLK_F5, "F5", "launch velocity up (Shift: down): by 10 m/s below 1000 m/s, by 100 m/s from 1000 m/s",
            [this](int direction) { changeVelocity(direction); });
  }

  void addOptions(CLI::App& app) override {
    app.add_option("--velocity", velocity_, "launch velocity in m/s (window: the starting F5 value)")
        ->check(cli::positive(1e7))
        ->capture_default_str();
    launchesOption_ = app.add_option("--launches", launches_,
                                     "headless: cubes launched one at a time (the previous one removed) at "
                                     "--velocity; with --find-max-velocity, launches per tested velocity "
                                     "(default 5, or 1 when scanning)")
                          ->check(CLI::Range(1, 100000));
    app.add_flag("--find-max-velocity", findMaxVelocity_,
                 "headless: scan launch velocities from 1 m/s, every 1 m/s up to 1000 m/s and every 0.1% above, "
                 "for the highest velocity at which every launch so far was stopped");
    scanOptions_.push_back(
        app.add_option("--scan-limit", scanLimit_, "--find-max-velocity gives up above this velocity (m/s)")
            ->check(cli::positive(1e7))
            ->capture_default_str());
    scanOptions_.push_back(
        app.add_option("--band-factor", bandFactor_,
                       "--find-max-velocity keeps scanning up to this multiple of the first failing velocity, to "
                       "show whether stops reappear above it")
            ->check(cli::finiteRange(1.0, 100.0))
            ->capture_default_str());
    app.add_flag("--phase-jitter", phaseJitter_,
                 "start each launch up to one step's travel behind [-4, 3, 0] (uniform, from --seed), so the "
                 "cube meets the wall at a random phase of the step; off: the thesis's fixed launch point");
  }

  void checkOptions() const override {
    for (const CLI::Option* option : scanOptions_)
      if (option->count() && !findMaxVelocity_)
        throw UsageError(option->get_name() + ": only used with --find-max-velocity");
  }

 protected:
  void configureWorld() override { dWorldSetContactSurfaceLayer(world(), SURFACE_LAYER); }

  void buildScene() override {
    add<Plane>(space());
    Box& wall = add<Box>(world(), space(), WALL_THICKNESS, WALL_HEIGHT, WALL_WIDTH, 1.0);
    wall.setAsFixedGeom();
    wall.setPosition(WALL_X, WALL_HEIGHT / 2, 0.0);
    wall.color = Color{0.45f, 0.55f, 0.7f};
    launchesInScene_.clear();
    launched_ = stopped_ = passed_ = 0;
    if (findMaxVelocity_ && !options().headless)
      notify("--find-max-velocity runs only with --headless; B launches here");
  }

  void afterStep() override {
    for (Launch& l : launchesInScene_) {
      if (l.outcome != Outcome::InFlight) continue;
      l.outcome = classify(l);
      if (l.outcome == Outcome::InFlight) continue;
      (l.outcome == Outcome::Passed ? passed_ : stopped_) += 1;
      l.cube->color = l.outcome == Outcome::Passed ? Color{0.9f, 0.25f, 0.2f} : Color{0.3f, 0.8f, 0.35f};
      lastOutcome_ = l.outcome;
      lastVelocity_ = l.velocity;
    }
    removeFarCubes();
  }

  void addHudLines(std::vector<std::string>& lines) const override {
    lines.push_back("launch velocity " + format(velocity_) + " m/s   B launches a cube, F5 / Shift+F5 change it");
    std::string counts = "launched " + std::to_string(launched_) + ": stopped " + std::to_string(stopped_) +
                         ", passed through " + std::to_string(passed_);
    if (lastOutcome_ != Outcome::InFlight)
      counts += "   (last: " + std::string(outcomeName(lastOutcome_)) + " at " + format(lastVelocity_) + " m/s)";
    lines.push_back(counts);
    lines.push_back("every arrival is stopped below (h + t/2)/step = " + format(guaranteedStopVelocity()) +
                    " m/s; (h + t)/step = " + format(geometricPrediction()) + " m/s");
  }

  void addMetrics(Metrics& m) const override {
    m.set("launch_velocity", findMaxVelocity_ ? 0.0 : velocity_);
    m.set("launches", launched_);
    m.set("stopped", stopped_);
    m.set("passed_through", passed_);
    m.set("geometric_prediction", geometricPrediction());
    m.set("guaranteed_stop_velocity", guaranteedStopVelocity());
    if (!findMaxVelocity_) return;
    m.set("max_velocity", scan_.maxVelocity);
    m.set("max_velocity_resolution", scan_.maxVelocityResolution);
    m.set("first_failure_velocity", scan_.firstFailure);
    m.set("band_upper_velocity", scan_.bandUpper);
    m.set("velocities_stopped_in_band", scan_.stoppedInBand);
    m.set("velocities_passed_in_band", scan_.passedInBand);
    m.set("highest_stopped_velocity_in_band", scan_.highestStoppedInBand);
    m.set("tested_velocities", scan_.tested);
  }

  void onSettingChanged(const std::string&) override {
    // The surface layer is not part of WorldSettings; keep it at the thesis's value.
    dWorldSetContactSurfaceLayer(world(), SURFACE_LAYER);
  }

  void initialCamera(Camera& camera) const override { camera.lookAt({-7.5, 4.5, 8.5}, {-1.5, 2.2, 0.0}); }
  SceneBounds bounds() const override { return {{-1.5, 2.5, 0.0}, 6.0}; }

  int runHeadless() override {
    if (findMaxVelocity_) {
      findMaxVelocity();
    } else {
      for (int i = 0; i < launchCount(5); ++i)
        if (launchAndResolve(velocity_) == Outcome::InFlight) break;  // blew up
    }
    return reportHeadless();
  }

 private:
  static WorldSettings settingsForThisScene() {
    WorldSettings s;
    s.erp = ERP;
    s.cfm = CFM;
    return s;
  }

  double geometricPrediction() const { return (CUBE_HALF + WALL_THICKNESS) / settings().step; }
  double guaranteedStopVelocity() const { return (CUBE_HALF + WALL_THICKNESS / 2) / settings().step; }

  int launchCount(int fallback) const { return launchesOption_ && launchesOption_->count() ? launches_ : fallback; }

  void changeVelocity(int direction) {
    const bool coarse = direction > 0 ? velocity_ >= F5_COARSE_FROM : velocity_ > F5_COARSE_FROM;
    velocity_ = std::max(F5_FINE_STEP, velocity_ + direction * (coarse ? F5_COARSE_STEP : F5_FINE_STEP));
    notify("launch velocity " + format(velocity_) + " m/s");
  }

  Launch& launch(double velocity) {
    Box& cube = add<Box>(world(), space(), CUBE_SIDE, CUBE_SIDE, CUBE_SIDE, CUBE_MASS);
    double startX = LAUNCH_X;
    if (phaseJitter_) startX -= std::uniform_real_distribution<double>(0.0, 1.0)(random()) * velocity * settings().step;
    cube.setPosition(startX, LAUNCH_Y, LAUNCH_Z);
    cube.setLinearVelocity(velocity, 0.0, 0.0);
    cube.color = Color{0.95f, 0.8f, 0.2f};
    ++launched_;
    launchesInScene_.push_back({&cube, velocity, simulatedTime()});
    return launchesInScene_.back();
  }

  // Passed: the whole cube is beyond the far face. Stopped: on the near side
  // of the mid-plane and no longer moving toward the wall (bounced back, or
  // fell to the ground short of it). Otherwise still in flight until the
  // time it needs to reach the wall plus SETTLE_SECONDS; then its centre decides.
  Outcome classify(const Launch& l) const {
    const double x = l.cube->getPosition()[0];
    const double vx = dBodyGetLinearVel(l.cube->getBody())[0];
    if (x - CUBE_HALF > WALL_FAR_FACE) return Outcome::Passed;
    if (vx <= 0.0 && x < WALL_X) return Outcome::Stopped;
    const double reachSeconds = (WALL_FAR_FACE + CUBE_HALF - LAUNCH_X) / l.velocity;
    if (simulatedTime() - l.launchedAt > reachSeconds + SETTLE_SECONDS)
      return x > WALL_FAR_FACE ? Outcome::Passed : Outcome::Stopped;
    return Outcome::InFlight;
  }

  void removeFarCubes() {
    removeIf([this](const AbstractObject& object) {
      for (auto it = launchesInScene_.begin(); it != launchesInScene_.end(); ++it) {
        if (it->cube != &object || it->outcome == Outcome::InFlight) continue;
        const dReal* p = object.getPosition();
        if (std::fabs(p[0]) < KEEP_RADIUS && p[1] > -KEEP_RADIUS) return false;
        launchesInScene_.erase(it);
        return true;
      }
      return false;
    });
  }

  // Headless: one launch on its own (the previous cube removed), stepped until
  // its outcome is known. InFlight means the simulation blew up.
  Outcome launchAndResolve(double velocity) {
    removeIf([this](const AbstractObject& object) {
      for (const Launch& l : launchesInScene_)
        if (l.cube == &object) return true;
      return false;
    });
    launchesInScene_.clear();
    launch(velocity);
    while (launchesInScene_.back().outcome == Outcome::InFlight)
      if (!runFor(settings().step)) return Outcome::InFlight;
    return launchesInScene_.back().outcome;
  }

  // True when every launch at this velocity was stopped; false when one passed
  // or the simulation blew up (then `blewUp` is set).
  bool everyLaunchStopped(double velocity, bool& blewUp) {
    bool all = true;
    for (int i = 0; i < launchCount(1); ++i) {
      const Outcome outcome = launchAndResolve(velocity);
      if (outcome == Outcome::InFlight) {
        blewUp = true;
        return false;
      }
      all = all && outcome == Outcome::Stopped;
    }
    return all;
  }

  static double nextScanVelocity(double velocity) {
    return velocity < SCAN_FINE_LIMIT ? velocity + SCAN_FINE_STEP : velocity * (1.0 + SCAN_COARSE_RATIO);
  }
  static double resolutionAt(double velocity) {
    return velocity < SCAN_FINE_LIMIT ? SCAN_FINE_STEP : velocity * SCAN_COARSE_RATIO;
  }

  // Scans upward; max_velocity is the last velocity before the first one with
  // a passing launch. After the first failure it keeps going to
  // band-factor x that velocity, counting the velocities that stop again.
  void findMaxVelocity() {
    bool blewUp = false;
    for (double v = SCAN_FINE_STEP; v <= scanLimit_ * (1 + 1e-12) && !blewUp; v = nextScanVelocity(v)) {
      if (scan_.firstFailure > 0.0 && v > scan_.bandUpper) break;
      const bool stopped = everyLaunchStopped(v, blewUp);
      if (blewUp) break;
      ++scan_.tested;
      if (scan_.firstFailure == 0.0) {
        if (stopped) {
          scan_.maxVelocity = v;
          continue;
        }
        scan_.firstFailure = v;
        scan_.bandUpper = std::min(scanLimit_, v * bandFactor_);
        continue;
      }
      if (stopped) {
        ++scan_.stoppedInBand;
        scan_.highestStoppedInBand = v;
      } else {
        ++scan_.passedInBand;
      }
    }
    scan_.maxVelocityResolution = resolutionAt(scan_.maxVelocity);
    printScanSummary(blewUp);
  }

  void printScanSummary(bool blewUp) const {
    std::cout << "scan: every 1 m/s up to 1000 m/s, every 0.1% above; " << launchCount(1) << " launch(es) per velocity"
              << (phaseJitter_ ? ", random phase" : ", fixed launch point") << '\n';
    if (blewUp) std::cout << "scan: stopped early, the simulation blew up\n";
    if (scan_.firstFailure == 0.0) {
      std::cout << "scan: no launch passed up to the scan limit " << format(scanLimit_) << " m/s\n";
      return;
    }
    std::cout << "max velocity " << format(scan_.maxVelocity) << " m/s (resolution "
              << format(scan_.maxVelocityResolution) << " m/s): every launch up to it was stopped; first launch "
              << "through at " << format(scan_.firstFailure) << " m/s\n";
    std::cout << "band " << format(scan_.firstFailure) << " - " << format(scan_.bandUpper)
              << " m/s: " << scan_.stoppedInBand << " tested velocities stopped again, " << scan_.passedInBand
              << " passed"
              << (scan_.stoppedInBand ? " (highest stopped " + format(scan_.highestStoppedInBand) + " m/s)" : "")
              << '\n';
  }

  struct ScanResult {
    double maxVelocity = 0.0;
    double maxVelocityResolution = 0.0;
    double firstFailure = 0.0;  // 0: none found up to the scan limit
    double bandUpper = 0.0;
    int stoppedInBand = 0;
    int passedInBand = 0;
    double highestStoppedInBand = 0.0;
    int tested = 0;
  };

  double velocity_ = DEFAULT_VELOCITY;
  int launches_ = 1;
  CLI::Option* launchesOption_ = nullptr;
  std::vector<const CLI::Option*> scanOptions_;
  bool findMaxVelocity_ = false;
  double scanLimit_ = DEFAULT_SCAN_LIMIT;
  double bandFactor_ = DEFAULT_BAND_FACTOR;
  bool phaseJitter_ = false;

  std::vector<Launch> launchesInScene_;
  int launched_ = 0, stopped_ = 0, passed_ = 0;
  Outcome lastOutcome_ = Outcome::InFlight;
  double lastVelocity_ = 0.0;
  ScanResult scan_;
};

}  // namespace

int main(int argc, char** argv) {
  return odelab::runTest<MaximumVelocity>(
      argc, argv, "Cubes launched at a thin wall: the highest velocity at which the wall still stops every one.");
}
