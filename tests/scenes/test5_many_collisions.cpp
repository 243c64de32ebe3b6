// test5 - Lots of same collisions (thesis 5.6, "Mnoho stejnych kolizi"):
// flat plates [5.0, 0.05, 5.0] dropped one by one onto a static platform
// stack into a column, so every new plate adds another large face-to-face
// contact to the pile. ERP 0.2 and CFM exactly 0 with plain contacts (no
// bounce, soft ERP or soft CFM), auto-disable off (`--auto-disable` turns it
// on, with the thesis's thresholds to try). The thesis found the stack
// builds cleanly but the program slows as it grows, that a hash space lets it
// grow twice as high, and that any CFM > 0 (e.g. 1e-4) makes a tall stack
// twist and collapse.
//
// Measures the cost of a step as the stack grows (ms_per_step over the last
// simulated second), the stack's height and how straight it stays (the
// largest sideways offset of a plate centre from the stack's axis).
// `--threads N` steps the world with ODE's threaded island stepping, so its
// effect on the cost can be measured (a single stack is one island).
#include <CLI/CLI.hpp>

#include <ctime>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "AbstractWindow.h"
#include "Box.h"
#include "CommandLine.h"
#include "SceneRegistry.h"
#include "shared/SceneConstants.h"
#include "shared/IslandThreads.h"
#include "shared/PlateStack.h"
#include "shared/StepCostWindow.h"

#include <ode/threading_impl.h>

namespace {

using namespace odelab;

using namespace scene::test5;  // the platform, the plates and their drops: SceneConstants.h (shared with peers/)
// ODE's default auto-disable thresholds (m/s and rad/s); the thesis tried
// raising the linear one to 0.3.
constexpr double ODE_DEFAULT_DISABLE_THRESHOLD = 0.01;
constexpr int MAX_THREADS = 64;

WorldSettings settingsForThisScene() {
  WorldSettings settings;  // step 0.001, QuickStep with 20 iterations
  settings.erp = 0.2;
  settings.cfm = 0.0;  // the thesis: "the only CFM that works is zero"
  return settings;
}

class ManyCollisions : public AbstractWindow {
 public:
  ManyCollisions() : AbstractWindow(settingsForThisScene()) {
    bindKey(SDLK_n, "N", "drop a plate [5, 0.05, 5] at height 6 (or 1 m above the stack once it nears 6 m)",
            [this](int) { spawnPlate(); });
    // Read where it is in force: --space before the world is made, the
    // world's space after (Q changes it at once, and it persists across R).
    declare(Knob::choice(
                "space", "collision space", {"simple", "hash", "sap", "quadtree"},
                {"dSimpleSpaceCreate", "dHashSpaceCreate", "dSweepAndPruneSpaceCreate", "dQuadTreeSpaceCreate"},
                [this] { return static_cast<int>(world() ? spaceKind() : requestedSpace_); },
                [this](int choice) {
                  requestedSpace_ = static_cast<SpaceKind>(choice);
                  if (world()) setSpaceKind(requestedSpace_);
                })
                .withOption("--space", "collision space: simple, hash (dHashSpaceCreate), sap (sweep and prune) or quadtree")
                .withKey(SDLK_q, "Q", "next collision space: simple -> hash -> sap -> quadtree (Shift: back)"));
    declareKnobs();
    useContactChoices(dInfinity);  // the thesis names no friction here: never slides
    timeSteps();                   // ms_per_step and the collide cost read each step's wall time
  }

  // The world must let go of the threading implementation before it is
  // freed; the base destroys the world only after this destructor.
  ~ManyCollisions() override {
    if (world()) dWorldSetStepThreadingImplementation(world(), nullptr, nullptr);
  }

 protected:
  void configureWorld() override {
    // The thesis's conclusion: auto-disable only postpones the slow-down and can
    // freeze plates before they land, so it stays off unless asked for.
    dWorldSetAutoDisableFlag(world(), autoDisable_ ? 1 : 0);
    dWorldSetAutoDisableLinearThreshold(world(), disableLinear_);
    dWorldSetAutoDisableAngularThreshold(world(), disableAngular_);
    dWorldSetContactMaxCorrectingVel(world(), maxCorrectingVel_);  // dInfinity unless given
    dWorldSetContactSurfaceLayer(world(), surfaceLayer_);
    if (threads_ > 1) {
      if (!islandThreads_) islandThreads_ = std::make_unique<IslandThreads>(threads_);
      islandThreads_->attach(world());
    }
    if (!spaceChosen_) {  // --space once; later changes (Q, the panel) persist across R
      setSpaceKind(requestedSpace_);
      spaceChosen_ = true;
    }
  }

  void buildScene() override {
    Box& platform = add<Box>(world(), space(), PLATFORM_SIDE, PLATFORM_THICKNESS, PLATFORM_SIDE, 1.0);
    platform.setAsFixedGeom();
    platform.setPosition(0.0, -PLATFORM_THICKNESS / 2, 0.0);
    platform.color = Color{0.45f, 0.5f, 0.55f};
    plates_.clear();
    cost_.clear();
    cpuCost_.clear();
    lastCpuClock_ = std::clock();
    collidedSeconds_ = 0.0;
    nextSpawn_ = 0.0;
    firstPlateDropped_ = false;
  }

  // Plain contacts, as the thesis's near callback: mode 0 (no bounce, no
  // soft ERP/CFM); mu dInfinity as in the other scenes.
  void setContactSurface(dGeomID, dGeomID, dSurfaceParameters& surface) override {
    surface.mode = 0;
    surface.mu = contactMu();
  }

  void afterStep() override {
    cost_.add(simulatedTime(), lastStepWallSeconds());
    // The process's CPU time since the last step: what the step cost with a
    // core to itself, whatever else the machine runs (the lab's real-time rule).
    const std::clock_t now = std::clock();
    cpuCost_.add(simulatedTime(), static_cast<double>(now - lastCpuClock_) / CLOCKS_PER_SEC);
    lastCpuClock_ = now;
    collidedSeconds_ += lastStepWallSeconds();
    plates_.markLanded(simulatedTime());
    // A window with no timed spawning still drops its first plate at once,
    // so it opens on a plate falling onto the platform (N drops the next).
    if (!options().headless && spawnInterval() <= 0 && !firstPlateDropped_) {
      spawnPlate();
      firstPlateDropped_ = true;
    }
    const double interval = spawnInterval();
    if (interval > 0 && static_cast<int>(plates_.size()) < plateLimit() && simulatedTime() >= nextSpawn_) {
      spawnPlate();
      nextSpawn_ += interval;
    }
  }

  void addHudLines(std::vector<std::string>& lines) const override {
    std::ostringstream s;
    s << std::fixed << "plates " << plates_.size() << " (" << plates_.landedCount() << " landed)   stack height "
      << std::setprecision(3) << plates_.height() << " m   max axis offset " << std::setprecision(4) << plates_.maxAxisOffset()
      << " m   max twist " << std::setprecision(2) << plates_.maxTwistDegrees() << " deg";
    lines.push_back(s.str());
    s.str("");
    s << std::setprecision(3) << "collide + step: " << cost_.meanMilliseconds()
      << " ms per step over the last simulated second   N plate, Q space";
    lines.push_back(s.str());
    s.str("");
    s << "auto-disable ";
    if (autoDisable_)
      s << "on, thresholds " << disableLinear_ << " m/s / " << disableAngular_ << " rad/s ("
        << plates_.frozenInAirCount() << " plates frozen in the air)";
    else
      s << "off";
    s << "   island stepping threads " << threads_;
    if (threads_ > 1) s << " (not reproducible: runs and rewinds differ)";
    lines.push_back(s.str());
  }

  // Threaded island stepping finishes islands in whatever order the
  // threads do, so the same seed need not give the same state.
  std::string rewindCaveat() const override {
    return threads_ > 1 ? "--threads " + std::to_string(threads_) + ": the replay need not match the run it rewinds"
                        : std::string();
  }

  void addMetrics(Metrics& m) const override {
    m.set("reproducible", threads_ > 1 ? 0 : 1);
    m.set("plates", static_cast<double>(plates_.size()));
    m.set("landed_plates", plates_.landedCount());
    m.set("ms_per_step", cost_.meanMilliseconds());
    m.set("cpu_ms_per_step", cpuCost_.meanMilliseconds());
    m.set("max_axis_offset", plates_.maxAxisOffset());
    m.set("stack_height", plates_.height());
    m.set("plate_thickness_m", PLATE_THICKNESS);  // the lab's stack rule needs it
    m.set("max_twist_degrees", plates_.maxTwistDegrees());
    m.set("plates_frozen_in_air", plates_.frozenInAirCount());
    m.set("auto_disable", autoDisable_ ? 1 : 0);
    m.set("threads", threads_);
    // Wall time inside collide + step + empty over the whole run; the rest of
    // wall_seconds is the framework's and this scene's own bookkeeping.
    m.set("collide_step_seconds", collidedSeconds_);
  }

  // The thesis's slow-down, live: cost of a step against simulated time.
  bool plotValue(double& value) const override {
    value = cost_.meanMilliseconds();
    return true;
  }
  std::string plotLabel() const override { return "collide + step (ms per step, last simulated second)"; }

  double defaultHeadlessSeconds() const override { return RUN_SECONDS; }

  void initialCamera(Camera& camera) const override { camera.lookAt({12, 6, 17}, {0, 3.8, 0}); }

  SceneBounds bounds() const override { return {{0, 3, 0}, 8.0}; }

 private:
  // The scene's knobs, each declared with its default (the headless one
  // for --plates and --spawn-interval: the window spawns by itself only once
  // the interval is given or changed). The world values are set in
  // configureWorld(), when the scene is built: a new one rebuilds it.
  void declareKnobs() {
    declare(Knob::integer("plates", "plates", plateLimit_, 1, 100000)
                .withOption("--plates", "timed spawning stops after N plates (default: 50 headless)")
                .defaultPickedByScene());
    spawnKnob_ = &declare(Knob::interval("spawn_interval", "spawn interval", spawnInterval_, 1e-6, 1e6)
                .withOption("--spawn-interval",
                            "drop a plate every S simulated seconds (default: 0.3 headless; in the window the "
                            "first plate at once, then N)")
                .defaultPickedByScene());
    declare(Knob::toggle("auto_disable", "auto-disable", autoDisable_)
                .withOption("--auto-disable",
                            "let ODE disable resting plates (default off: the thesis found it freezes plates in the air)")
                .rebuildsScene());
    declare(Knob::real("auto_disable_linear", "auto-disable linear threshold", "m/s", disableLinear_, 0.0, 1e6)
                               .withOption("--auto-disable-linear",
                                           "auto-disable linear velocity threshold, m/s (default ODE's 0.01; the "
                                           "thesis tried 0.3)")
                               .onlyWith("--auto-disable")
                               .rebuildsScene());
    declare(Knob::real("auto_disable_angular", "auto-disable angular threshold", "rad/s", disableAngular_,
                                       0.0, 1e6)
                                .withOption("--auto-disable-angular",
                                            "auto-disable angular velocity threshold, rad/s (default ODE's 0.01)")
                                .onlyWith("--auto-disable")
                                .rebuildsScene());
    declare(Knob::real("contact_max_correcting_vel", "contact max correcting velocity", "m/s", maxCorrectingVel_, 1e-6, 0)
                .upToInfinity(1e9)
                .withOption("--contact-max-correcting-vel",
                            "dWorldSetContactMaxCorrectingVel: the fastest a contact pushes bodies apart to undo "
                            "penetration, m/s, or inf (default ODE's: inf, unlimited)")
                .rebuildsScene());
    declare(Knob::real("contact_surface_layer", "contact surface layer", "m", surfaceLayer_, 0.0, 0.1)
                .withOption("--contact-surface-layer",
                            "dWorldSetContactSurfaceLayer: penetration depth a contact leaves alone, m (default ODE's 0)")
                .rebuildsScene());
    declare(Knob::integer("threads", "threads", threads_, 1, MAX_THREADS)
                .withOption("--threads", "threads for ODE's threaded island stepping (default 1: not threaded)")
                .rebuildsScene());
  }

  // The window drops plates by itself (timed) only once the interval is
  // given or changed; until then its first plate falls at once, N the next.
  double spawnInterval() const {
    const bool given = spawnKnob_->parsed && spawnKnob_->parsed->count() > 0;
    return options().headless || given || spawnChanged_ ? spawnInterval_ : 0.0;
  }
  int plateLimit() const { return plateLimit_; }

  void onKnobChanged(const Knob& knob) override {
    if (&knob == spawnKnob_) spawnChanged_ = true;
  }

  void spawnPlate() {
    Box& plate = add<Box>(world(), space(), PLATE_WIDTH, PLATE_THICKNESS, PLATE_WIDTH, PLATE_MASS);
    plate.setPosition(0.0, plates_.spawnHeight(), 0.0);
    const float shade = 0.55f + 0.4f * static_cast<float>(plates_.size() % 5) / 4.0f;
    plate.color = Color{shade, 0.75f * shade, 0.35f};
    plates_.add(&plate, simulatedTime());
  }

  PlateStack plates_;
  StepCostWindow cost_{COST_WINDOW};
  StepCostWindow cpuCost_{COST_WINDOW};  // process CPU time per step (all threads, the whole step loop)
  std::clock_t lastCpuClock_ = 0;
  double collidedSeconds_ = 0.0;
  double nextSpawn_ = 0.0;
  bool firstPlateDropped_ = false;  // the window's first plate (no timed spawning)
  double spawnInterval_ = DEFAULT_SPAWN_INTERVAL;
  int plateLimit_ = DEFAULT_PLATES;
  const Knob* spawnKnob_ = nullptr;
  bool spawnChanged_ = false;  // on the panel or by a replay: the window spawns by it
  SpaceKind requestedSpace_ = SpaceKind::Simple;
  bool spaceChosen_ = false;
  bool autoDisable_ = false;
  double disableLinear_ = ODE_DEFAULT_DISABLE_THRESHOLD;
  double disableAngular_ = ODE_DEFAULT_DISABLE_THRESHOLD;
  int threads_ = 1;
  double maxCorrectingVel_ = dInfinity;  // ODE's own default: unlimited
  double surfaceLayer_ = 0.0;
  std::unique_ptr<IslandThreads> islandThreads_;  // only with --threads > 1
};

}  // namespace

ODELAB_SCENE(ManyCollisions,
             "Plates [5, 0.05, 5] dropped onto a stack; how fast and how straight does it grow?")
