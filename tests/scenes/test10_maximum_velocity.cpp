// test10 - Maximum velocity (thesis 5.11): small cubes are launched at a thin
// vertical wall. ODE tests collisions only at the start of each step (no
// continuous collision detection), so a fast enough cube jumps over the wall
// or lands past its middle and is pushed out of the far side. The test finds
// the highest launch velocity at which every cube is still stopped.
//
// Measures: whether each launch passed through (its centre ends beyond the
// wall's far face); with --find-max-velocity, the highest velocity V such
// that every launch at every tested velocity up to V was stopped
// (tests/shared/VelocityScan.h).
//
// Geometry of the limit: a cube of half-size h crossing a wall of thickness t
// overlaps it while its centre lies within h + t/2 of the wall's mid-plane.
// At the first step that overlaps, the box-box test pushes the cube out along
// the axis of least penetration: back if its centre is still short of the
// mid-plane, forward (through) if it is past it. So every arrival is stopped
// while one step's travel v*step is below h + t/2; above that it depends on
// where the cube happens to be at the steps around the wall (the phase), which
// for a fixed launch point is a fixed function of v.
//
// The remedy (--ccd, key T; off by default, the thesis's behaviour): before
// each step every fast body is swept along its motion in the step, turning
// included, against the static geometry (tests/shared/SweptCollision.h): moved to
// its first touching pose, with speculative contacts for the corners on
// their way in, so that the wall stops it through contacts, never by a
// velocity edit. Also measured: how often the sweep intervened and the
// energy a stopped cube keeps (max_stop_energy_ratio).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "AbstractWindow.h"
#include "Box.h"
#include "CommandLine.h"
#include "FormatValue.h"
#include "Plane.h"
#include "shared/SweptCollision.h"
#include "SceneRegistry.h"
#include "shared/LaunchOutcome.h"
#include "shared/LaunchTally.h"
#include "shared/FreeFlightCheck.h"
#include "MechanicalEnergy.h"
#include "shared/RandomTurn.h"
#include "shared/SceneConstants.h"
#include "shared/VelocityScan.h"

namespace {

using namespace odelab;
using namespace odelab::scene::test10;

constexpr double DEFAULT_VELOCITY = 200.0;  // m/s (proposed): stopped at the default step
// F5 changes the velocity by 10 m/s below 1000 m/s and by 100 m/s from there up.
constexpr double F5_FINE_STEP = 10.0, F5_COARSE_STEP = 100.0, F5_COARSE_FROM = 1000.0;
constexpr double DEFAULT_BAND_FACTOR = 1.5;      // keep scanning to 1.5x the first failure (proposed)

// The window keeps launched cubes to show where they ended; farther away they go.
constexpr double KEEP_RADIUS = 100.0;

class MaximumVelocity : public AbstractWindow {
 public:
  MaximumVelocity() : AbstractWindow(settingsForThisScene()) {
    bindKey(SDLK_b, "B", "launch a cube from [-4, 3, 0] toward the wall at the launch velocity",
            [this](int) { launch(velocity_); });
    declare(Knob::real("velocity", "launch velocity", "m/s", velocity_, 0.01, 1e7)
                .withOption("--velocity", "launch velocity in m/s (window: the starting F5 value)")
                .withKey(SDLK_F5, "F5", "launch velocity up (Shift: down): by 10 m/s below 1000 m/s, by 100 m/s from 1000 m/s")
                .steppedBy(nextVelocity)
                .logarithmic());
    declare(Knob::real("surface_layer", "contact surface layer", "m", surfaceLayer_, 0.0, 1.0)
                .withOption("--surface-layer", "contact surface layer, m: overlap ODE leaves uncorrected (the thesis: 0)")
                .rebuildsScene());  // set in configureWorld()
    launchesKnob_ = &declare(Knob::integer("launches", "launches", launches_, 1, 100000)
                                  .withOption("--launches",
                                              "headless: cubes launched one at a time (the previous one removed) at "
                                              "--velocity; with --find-max-velocity, launches per tested velocity "
                                              "(default 5, or 1 when scanning)")
                                  .onlyHeadless()
                                  .defaultPickedByScene());  // launchCount() picks it unless given
    declare(Knob::real("scan_limit", "scan limit", "m/s", scanLimit_, 1.0, 1e7)
                .withOption("--scan-limit", "--find-max-velocity gives up above this velocity (m/s)")
                .onlyWith("--find-max-velocity")
                .onlyHeadless());
    declare(Knob::real("band_factor", "band factor", "", bandFactor_, 1.0, 100.0)
                .withOption("--band-factor",
                            "--find-max-velocity keeps scanning up to this multiple of the first failing velocity, "
                            "to show whether stops reappear above it")
                .onlyWith("--find-max-velocity")
                .onlyHeadless());
    declare(Knob::real("spin", "launch spin", "rad/s", spin_, 0.0, 1e6)
                .withOption("--spin",
                            "launch each cube turning at this rate (rad/s) about a random axis (from --seed): a limit "
                            "of --ccd, whose step model is a constant turn"));
    // T (tunnelling): C is the shared key for the contact markers.
    declare(Knob::toggle("ccd", "continuous collision for fast bodies", ccd_)
                .withOption("--ccd",
                            "continuous collision for fast bodies: before each step, a body whose points may move more "
                            "than half its smallest half-extent in the step is swept along its motion (turning "
                            "included) against the static geometry, moved to its first touching pose and given "
                            "contacts for the corners on their way in, so the contacts stop it (window: T); off: the "
                            "thesis's behaviour")
                .withKey(SDLK_t, "T",
                         "continuous collision for fast bodies on / off (--ccd): sweep each fast body's step against "
                         "the static geometry"));
    declare(Knob::toggle("phase_jitter", "launch phase jitter", phaseJitter_)
                .withOption("--phase-jitter",
                            "start each launch up to one step's travel behind [-4, 3, 0] (uniform, from --seed), so "
                            "the cube meets the wall at a random phase of the step; off: the thesis's fixed launch "
                            "point"));
    declare(Knob::toggle("random_orientation", "launch at a random orientation", randomOrientation_)
                .withOption("--random-orientation",
                            "launch each cube turned to a uniformly random orientation (from --seed), so it meets the "
                            "wall with a corner or an edge first; off: unturned, face on (the thesis's)"));
    useContactChoices(dInfinity);  // the thesis names no friction here: never slides
  }

  void addOptions(CLI::App& app) override {
    app.add_flag("--find-max-velocity", findMaxVelocity_,
             "headless: scan launch velocities from 1 m/s, every 1 m/s up to 1000 m/s and every 0.1% above, "
             "for the highest velocity at which every launch so far was stopped");
  }

 protected:
  void configureWorld() override { dWorldSetContactSurfaceLayer(world(), surfaceLayer_); }

  void buildScene() override {
    Plane& ground = add<Plane>(space(), 0.0, 1.0, 0.0, GROUND_Y);
    Box& wall = add<Box>(world(), space(), WALL_THICKNESS, WALL_HEIGHT, WALL_WIDTH, 1.0);
    wall.setAsFixedGeom();
    wall.setPosition(WALL_X, GROUND_Y + WALL_HEIGHT / 2, 0.0);
    wall.color = Color{0.45f, 0.55f, 0.7f};
    sweep_.setStaticGeoms({ground.getGeom(), wall.getGeom()});
    sweep_.resetCounts();
    tally_.clear();
    freeFlight_.clear();
    if (findMaxVelocity_ && !options().headless)
      notify("--find-max-velocity runs only with --headless; B launches here");
    // A window opens (and R restarts) with a cube on its way to the wall at the launch
    // velocity, so the first second shows if it stops; headless launches are the measurement's.
    if (!options().headless) launch(velocity_);
  }

  // The remedy: the cubes are the scene's only bodies.
  void beforeStep() override {
    if (!ccd_) return;
    dVector3 gravity;
    dWorldGetGravity(world(), gravity);
    const double g[3] = {gravity[0], gravity[1], gravity[2]};
    for (const Launch& l : tally_.inScene) sweep_.sweep(l.sweptBody, settings().step, g, world(), contactGroup());
  }

  void afterStep() override {
    freeFlight_.afterStep(settings().step);
    // test10's rule (shared/LaunchOutcome.h), which the peer engines use too.
    tally_.classify(simulatedTime(), world(), [this](Launch& l) {
      l.cube->color = l.outcome == Outcome::Passed ? Color{0.9f, 0.25f, 0.2f} : Color{0.3f, 0.8f, 0.35f};
      if (l.outcome == Outcome::Passed && !options().headless) keepInView(*l.cube);
    });
    removeFarCubes();
  }

  void addHudLines(std::vector<std::string>& lines) const override {
    // The headline (the compact HUD's line): what happened to the launches.
    lines.push_back(tally_.countsText() + "   velocity " + formatValue(velocity_) + " m/s (B launches, F5 changes)");
    lines.push_back("passing windows: none below (h + t/2)/step = " + formatValue(guaranteedStopVelocity()) +
                    " m/s; above it the phase at the wall decides, (h + t)/step = " +
                    formatValue(geometricPrediction()) + " m/s; --find-max-velocity scans them");
    lines.push_back(std::string("continuous collision (T): ") +
                    (ccd_ ? "on, " + std::to_string(sweep_.counts().clamps) + " clamps" : std::string("off")));
  }

  // The live plot (L): the scene's headline measurement.
  bool plotValue(double& value) const override {
    value = double(tally_.passed);
    return true;
  }
  std::string plotLabel() const override { return "launches that passed the wall (of all launched)"; }

  void addMetrics(Metrics& m) const override {
    m.set("surface_layer", surfaceLayer_);
    // The scene, for the lab and the peer engines: read here, not copied.
    reportScene(m);
    m.set("launch_velocity", findMaxVelocity_ ? 0.0 : velocity_);
    m.set("launch_spin", spin_);
    m.set("launches", tally_.launched);
    m.set("stopped", tally_.stopped);
    m.set("passed_through", tally_.passed);
    m.set("launches_slowed_before_wall", freeFlight_.slowed());  // by an engine's speed cap
    m.set("geometric_prediction", geometricPrediction());
    m.set("guaranteed_stop_velocity", guaranteedStopVelocity());
    m.set("ccd", ccd_ ? 1 : 0);
    m.set("ccd_sweeps", static_cast<double>(sweep_.counts().sweeps));
    m.set("ccd_clamps", static_cast<double>(sweep_.counts().clamps));
    m.set("ccd_speculative_contacts", static_cast<double>(sweep_.counts().speculativeContacts));
    m.set("ccd_unresolved", static_cast<double>(sweep_.counts().unresolved));
    m.set("max_stop_energy_ratio", tally_.maxStopEnergyRatio);
    if (findMaxVelocity_) VelocityScan::addMetrics(scan_, m);
  }

  // From beside the launch line, a little past the wall: the launch point on
  // the left, the wall edge-on in the middle, a passed cube on its right.
  void initialCamera(Camera& camera) const override { camera.lookAt({1.5, 3.8, 12.0}, {-1.6, 2.2, 0.0}); }
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

  double geometricPrediction() const { return (CUBE_HALF_SIZE + WALL_THICKNESS) / settings().step; }
  double guaranteedStopVelocity() const { return (CUBE_HALF_SIZE + WALL_THICKNESS / 2) / settings().step; }

  int launchCount(int fallback) const {
    return launchesKnob_->parsed && launchesKnob_->parsed->count() ? launches_ : fallback;
  }

  // F5: by 10 m/s below 1000 m/s, by 100 m/s from there; never below 10 m/s.
  static double nextVelocity(double velocity, int direction) {
    const bool coarse = direction > 0 ? velocity >= F5_COARSE_FROM : velocity > F5_COARSE_FROM;
    return std::max(F5_FINE_STEP, velocity + direction * (coarse ? F5_COARSE_STEP : F5_FINE_STEP));
  }


  void launch(double velocity) {
    Box& cube = add<Box>(world(), space(), CUBE_SIDE, CUBE_SIDE, CUBE_SIDE, CUBE_MASS);
    double startX = LAUNCH_X;
    if (phaseJitter_) startX -= std::uniform_real_distribution<double>(0.0, 1.0)(random()) * velocity * settings().step;
    cube.setPosition(startX, LAUNCH_Y, LAUNCH_Z);
    cube.setLinearVelocity(velocity, 0.0, 0.0);
    if (randomOrientation_) turnAtRandom(cube.getBody(), random());
    if (spin_ > 0.0) spinAtRandom(cube.getBody(), spin_, random());
    cube.color = Color{0.95f, 0.8f, 0.2f};
    tally_.add({&cube, SweptCollision::describeBody(cube.getBody(), cube.getGeom()), velocity, simulatedTime(),
                mechanicalEnergy(cube.getBody(), world())});
    freeFlight_.launched(&cube, startX, velocity);
  }

  // Drops the cubes whose outcome is known and that flew far away, with their records.
  void removeFarCubes() {
    removeIf([this](const AbstractObject& object) {
      for (auto it = tally_.inScene.begin(); it != tally_.inScene.end(); ++it) {
        if (it->cube != &object || it->outcome == Outcome::InFlight) continue;
        const dReal* p = object.getPosition();
        if (std::fabs(p[0]) < KEEP_RADIUS && p[1] > GROUND_Y - KEEP_RADIUS) return false;
        tally_.inScene.erase(it);
        return true;
      }
      return false;
    });
  }

  // Headless: one launch on its own (the previous cube removed), stepped until
  // its outcome is known. InFlight means the simulation blew up. The outcome
  // is read from the counts, not from the launch's record: a cube that flies
  // past KEEP_RADIUS in the step that decides it is removed with its record.
  Outcome launchAndResolve(double velocity) {
    removeIf([](const AbstractObject& object) { return object.getBody() != nullptr; });
    tally_.inScene.clear();
    launch(velocity);
    const int decidedBefore = tally_.decided();
    while (tally_.decided() == decidedBefore)
      if (!runFor(settings().step)) return Outcome::InFlight;
    return tally_.lastOutcome;
  }

  void findMaxVelocity() {
    const VelocityScan scan(scanLimit_, bandFactor_);
    scan_ = scan.run([this](double velocity) {
      bool all = true;
      for (int i = 0; i < launchCount(1); ++i) {
        const Outcome outcome = launchAndResolve(velocity);
        if (outcome == Outcome::InFlight) return VelocityScan::Trial::BlewUp;
        if (freeFlight_.slowedSinceAsked()) return VelocityScan::Trial::Slowed;
        all = all && outcome == Outcome::Stopped;
      }
      return all ? VelocityScan::Trial::AllStopped : VelocityScan::Trial::SomePassed;
    });
    std::ostringstream what;
    what << launchCount(1) << " launch(es) per velocity" << (phaseJitter_ ? ", random phase" : ", fixed launch point")
         << (randomOrientation_ ? ", random orientation" : "") << (ccd_ ? ", continuous collision on" : "");
    scan.print(scan_, what.str(), std::cout);
  }

  FreeFlightCheck freeFlight_;
  double velocity_ = DEFAULT_VELOCITY;
  int launches_ = 1;
  const Knob* launchesKnob_ = nullptr;
  bool findMaxVelocity_ = false;
  double scanLimit_ = DEFAULT_SCAN_LIMIT;
  double bandFactor_ = DEFAULT_BAND_FACTOR;
  bool phaseJitter_ = false;
  bool randomOrientation_ = false;
  double spin_ = 0.0;  // rad/s at launch
  bool ccd_ = false;

  LaunchTally tally_;
  SweptCollision sweep_;
  VelocityScan::Result scan_;
  double surfaceLayer_ = SURFACE_LAYER;
};

}  // namespace

ODELAB_SCENE(MaximumVelocity,
             "Cubes launched at a thin wall: the highest velocity at which the wall still stops every one.")
