#include "AbstractWindow.h"

#include <ode/version.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "ExitCodes.h"
#include "FormatValue.h"
#include "MeasurementLog.h"
#include "OdeMessages.h"
#include "StopSignal.h"
#include "WorldKnobs.h"

namespace odelab {

namespace {

// The most contacts per pair --max-contacts allows (the array's size).
constexpr int MAX_CONTACTS = ContactChoices::MOST_CONTACTS;
// The live plot samples every hundredth of a simulated second. Contact
// markers are capped so a huge pile cannot flood the renderer.
constexpr double CHART_INTERVAL = 0.01;
constexpr size_t MAX_CONTACT_MARKERS = 4096;

// Whether a window run given --seconds (0: none) has reached it. Headless
// runs take round(seconds / step) steps: within half a step of --seconds is
// that step at a constant step, and the nearest one after a change of step.
bool runLengthReached(double seconds, double simulatedTime, double step) {
  return seconds > 0 && simulatedTime >= seconds - 0.5 * step;
}

}  // namespace

AbstractWindow::AbstractWindow(WorldSettings defaults) : SceneSettings(defaults) {
  bindSharedKeys();
  for (Knob& knob : worldKnobs(settings_, increment_)) declare(std::move(knob));
  bindTimeAndViewKeys();
}

AbstractWindow::~AbstractWindow() { shutdown(); }

void AbstractWindow::addOptions(CLI::App& app) { (void)app; }

void AbstractWindow::initialize(const RunOptions& options) {
  options_ = options;
  time_.setMaximumFrameTime(options.maxFrameTime);
  hudMode_ = options.hud;
  runLog_.setTarget(joinPath(options.outDir, programName() + "_run_log.txt"), title_);
  initialCamera(camera_);
  createWorld();
  beginRun();
}

void AbstractWindow::reset() {
  rewind_.newEpoch();
  failure_.clear();
  destroyWorld();
  createWorld();
  beginRun();
}

// A new run begins: what the timeline replays starts from here.
void AbstractWindow::beginRun() { rewind_.begin({settings_, spaceKind_, increment_}); }

void AbstractWindow::replayTo(long long step) {
  rewind_.setReplaying(true);
  const RunStart& start = rewind_.restore();
  settings_ = start.settings;
  spaceKind_ = start.space;
  increment_ = start.increment;
  destroyWorld();
  createWorld();
  rewind_.timeline().rewindCursor();
  while (steps_ < step && stepOnce()) {
  }
  rewind_.setReplaying(false);
  time_.setPaused(true);
  const std::string caveat = rewindCaveat();
  if (!caveat.empty()) notify("warning: " + caveat);
}

void AbstractWindow::shutdown() {
  destroyWorld();
  freeThreading();
}

void AbstractWindow::createWorld() {
  // Everything random in a run derives from --seed, so a run is reproducible.
  random_.seed(options_.seed);
  dRandSetSeed(options_.seed);
  world_ = dWorldCreate();
  // The world steps with an implementation of its own rather than ODE's
  // default, which all worlds share, so that one an ODE error has left in
  // a bad state can be dropped with its world (advanceFrame). A scene may
  // replace it in configureWorld() (test5 --threads).
  if (!stepThreading_) stepThreading_ = dThreadingAllocateSelfThreadedImplementation();
  dWorldSetStepThreadingImplementation(world_, dThreadingImplementationGetFunctions(stepThreading_), stepThreading_);
  contactGroup_ = dJointGroupCreate(0);
  space_ = nullptr;
  setSpaceKind(spaceKind_);
  settings_.applyTo(world_);
  simulatedTime_ = 0.0;
  steps_ = 0;
  contactsLastStep_ = 0;
  wallSeconds_ = 0.0;
  blowUpReason_.clear();
  time_.resetClock();
  drag_.release();
  contactMarkers_.clear();
  chart_.clear();
  chart_.label = plotLabel();
  nextChartTime_ = 0.0;
  rewind_.worldRebuilt();
  configureWorld();
  buildScene();
}

void AbstractWindow::setSpaceKind(SpaceKind kind) {
  dSpaceID next = nullptr;
  switch (kind) {
    case SpaceKind::Simple: next = dSimpleSpaceCreate(nullptr); break;
    case SpaceKind::Hash: next = dHashSpaceCreate(nullptr); break;
    case SpaceKind::SweepAndPrune: next = dSweepAndPruneSpaceCreate(nullptr, dSAP_AXES_XZY); break;
    case SpaceKind::QuadTree: {
      // Centred on the scene, covering its bounds; y is up so the tree splits x and z.
      const SceneBounds b = bounds();
      const dVector3 centre{b.centre[0], b.centre[1], b.centre[2], 0};
      const dVector3 extents{4 * b.radius, 4 * b.radius, 4 * b.radius, 0};
      next = dQuadTreeSpaceCreate(nullptr, centre, extents, 6);
      break;
    }
  }
  // Space cleanup is off: geoms belong to their objects, not to the space.
  dSpaceSetCleanup(next, 0);
  if (space_) {
    // Every geom in the space is an object's (a scene adds geoms only
    // through objects). They are found through the objects, not the space:
    // ODE's quadtree space cannot list its geoms (dSpaceGetGeom fails with
    // "not yet implemented"), which input fuzzing found.
    for (const auto& object : objects_) {
      const dGeomID geom = object->getGeom();
      if (!geom || dGeomGetSpace(geom) != space_) continue;
      dSpaceRemove(space_, geom);
      dSpaceAdd(next, geom);
    }
    if (dSpaceGetNumGeoms(space_) != 0) throw std::logic_error("setSpaceKind: the space holds a geom of no object");
    dSpaceDestroy(space_);
  }
  space_ = next;
  spaceKind_ = kind;
}

void AbstractWindow::nearCallback(void* data, dGeomID o1, dGeomID o2) {
  auto* self = static_cast<AbstractWindow*>(data);
  const dBodyID b1 = dGeomGetBody(o1);
  const dBodyID b2 = dGeomGetBody(o2);
  // Static against static, parts of one composite body, and bodies already
  // joined by a non-contact joint never collide.
  if (!b1 && !b2) return;
  if (b1 == b2) return;
  if (b1 && b2 && dAreConnectedExcluding(b1, b2, dJointTypeContact)) return;

  dContact contact[MAX_CONTACTS];
  const int count = dCollide(o1, o2, self->maxContacts(), &contact[0].geom, sizeof(dContact));
  if (count <= 0) return;
  dSurfaceParameters surface{};
  self->setContactSurface(o1, o2, surface);
  for (int i = 0; i < count; ++i) {
    contact[i].surface = surface;
    dJointID joint = dJointCreateContact(self->world_, self->contactGroup_, &contact[i]);
    dJointAttach(joint, b1, b2);
  }
  self->contactsThisStep_ += count;
  if (self->viewFlags_.contacts)
    for (int i = 0; i < count && self->contactMarkers_.size() < MAX_CONTACT_MARKERS; ++i) {
      const dContactGeom& g = contact[i].geom;
      self->contactMarkers_.push_back({{float(g.pos[0]), float(g.pos[1]), float(g.pos[2])},
                                       {float(g.normal[0]), float(g.normal[1]), float(g.normal[2])},
                                       float(g.depth)});
    }
}

void AbstractWindow::setContactSurface(dGeomID, dGeomID, dSurfaceParameters& surface) {
  surface.mode = 0;
  surface.mu = contactMu();
}

void AbstractWindow::useContactChoices(double defaultMu) {
  contactChoicesUsed_ = true;
  contact_.mu = defaultMu;
  for (Knob& knob : contact_.knobs()) declare(std::move(knob));
}

bool AbstractWindow::stepOnce() {
  // The clock only for scenes that measure a step's wall time (test5): two
  // clock reads a step are a tenth of a one-ball scene's framework cost.
  const auto start = timeSteps_ ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
  // Inputs, the drag, contact markers, rewind marks and the live plot: none
  // can come or be seen inside runFor(), which skips their cost.
  const bool attended = !unattended_;
  if (attended) {
    rewind_.timeline().applyDue(steps_, [this](const TimelineEvent& event) { applyEvent(event); });
    drag_.pull(objects_, settings_.gravity);
    if (viewFlags_.contacts) contactMarkers_.clear();
  }
  contactsThisStep_ = 0;
  beforeStep();
  try {
    // Collision is timed only for the window's frame profile: a headless run
    // pays no clock reads.
    const auto collideStart = profileCollision_ ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
    dSpaceCollide(space_, this, &AbstractWindow::nearCallback);
    if (profileCollision_)
      collideWallSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - collideStart).count();
    if (settings_.solver == Solver::QuickStep)
      dWorldQuickStep(world_, settings_.step);
    else
      dWorldStep(world_, settings_.step);
  } catch (const OdeError& error) {
    // ODE's own checks often see a blow-up before stateProblem() does (a NaN
    // quaternion fails dxNormalize4): report it with the time and settings.
    throw OdeError(std::string(error.what()) + momentAndSettings());
  }
  dJointGroupEmpty(contactGroup_);
  contactsLastStep_ = contactsThisStep_;
  simulatedTime_ += settings_.step;
  ++steps_;
  if (timeSteps_) lastStepWallSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  afterStep();
  if (attended) {
    rewind_.afterStep(simulatedTime_, steps_);
    if (simulatedTime_ >= nextChartTime_) {
      double value;
      if (plotValue(value)) chart_.add(simulatedTime_, value);
      nextChartTime_ += CHART_INTERVAL;
    }
  }
  // Every step: a few multiplications per body; the message only when one looks wrong.
  if (!stateSuspicious()) return true;
  const std::string problem = stateProblem();
  if (problem.empty()) return true;
  blowUpReason_ = "simulation blew up: " + problem + momentAndSettings();
  return false;
}

std::string AbstractWindow::momentAndSettings() const {
  return " at t=" + formatValue(simulatedTime_) + " s" + settingsInForce();
}

void AbstractWindow::advanceFrame(double elapsedSeconds, double steppingBudget) {
  profileCollision_ = true;  // only a window advances by frames
  wallSeconds_ += elapsedSeconds;
  const int stepsNow = time_.stepsFor(elapsedSeconds, settings_.step);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < stepsNow; ++i) {
    // A run given --seconds ends on the step a headless run ends on, not
    // wherever the frame that crossed it ends: the last picture, the output
    // files and the metrics are those of that moment on any machine.
    if (runLengthReached(options_.seconds, simulatedTime_, settings_.step)) break;
    if (i > 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > steppingBudget) {
      time_.dropSteps(stepsNow - i);
      break;
    }
    std::string failure;
    try {
      if (!stepOnce()) failure = blowUpReason_;
    } catch (const OdeError& error) {
      // Headless, an ODE error ends the run (status 4). In a window the
      // session goes on: the world is torn down and the run replayed to the
      // last good step. The errors seen come from the solver and integrator
      // (dWorldStep with CFM 0 and unbounded friction fails dxNormalize4);
      // the box, sphere and plane colliders raise none, so the space is
      // never left locked mid-collision.
      failure = std::string("ODE error: ") + error.what();
      // The failed step left a job in the world's threading implementation;
      // freeing it would fail ODE's own check, so it is left allocated
      // (a few hundred bytes an error) and the next world gets a new one.
      stepThreading_ = nullptr;
    }
    if (!failure.empty()) {
      recoverFrom(failure);
      return;
    }
  }
  if (runLengthReached(options_.seconds, simulatedTime_, settings_.step)) quitRequested_ = true;
}

// A blow-up or an ODE error in a window: the run is replayed to the step
// before the failure and paused there, with the message on screen until it
// is dismissed; the timeline stays, so , rewinds further and R starts over.
void AbstractWindow::recoverFrom(const std::string& failure) {
  ++failures_;
  const long long lastGood = steps_ - 1;
  replayTo(std::max(0LL, lastGood));
  failure_ = failure + "; paused at the last good state, t=" + formatValue(simulatedTime_) +
             " s (Enter dismisses, , rewinds, R resets)";
  notify(failure_);
}

int AbstractWindow::runHeadless() {
  runFor(options_.seconds > 0 ? options_.seconds : defaultHeadlessSeconds());
  return reportHeadless();
}

bool AbstractWindow::runFor(double seconds) {
  const long long total = steps_ + std::llround(seconds / settings_.step);
  const auto start = std::chrono::steady_clock::now();
  bool finite = blowUpReason_.empty();
  {
    // Set for the loop only, and cleared even when a step throws.
    struct Unattended {
      bool& flag;
      ~Unattended() { flag = false; }
    } unattended{unattended_ = true};
    while (steps_ < total && finite && stopSignal() == 0) finite = stepOnce();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  wallSeconds_ += wall;
  time_.addRun(wall, seconds);
  return finite;
}

int AbstractWindow::reportHeadless() {
  if (stopSignal() != 0) return stoppedBySignal();
  endOutputs(blowUpReason_);
  const Metrics result = metrics();
  std::cout << title_ << ": " << formatValue(simulatedTime_) << " simulated seconds\n";
  result.print(std::cout);
  if (!options_.metricsJson.empty()) result.writeJsonAtomically(options_.metricsJson);
  if (!blowUpReason_.empty()) {
    std::cerr << "error: " << blowUpReason_ << '\n';
    return exit_code::BLEW_UP;
  }
  return exit_code::OK;
}

void AbstractWindow::endOutputs(const std::string& cutShortBecause) {
  const std::string where = "t=" + formatValue(simulatedTime_) + " s, " + std::to_string(steps_) + " steps";
  writeEndLine(cutShortBecause.empty() ? "complete: " + where : "incomplete: " + where + "; " + cutShortBecause);
}

// SIGINT or SIGTERM stopped the run: the files say so, no metrics are
// written as if the run were whole, and the status is the shell's 128 + N.
int AbstractWindow::stoppedBySignal() {
  endOutputs(std::string("stopped by ") + stopSignalName());
  std::cerr << "error: stopped by " << stopSignalName() << " at t=" << formatValue(simulatedTime_)
            << " s; no metrics written\n";
  return 128 + stopSignal();
}

Metrics AbstractWindow::metrics() const {
  Metrics m;
  m.set("steps", static_cast<double>(steps_));
  m.set("sim_seconds", simulatedTime_);
  m.set("wall_seconds", wallSeconds_);
  if (options_.headless) {
    m.set("real_time_factor", wallSeconds_ > 0 ? simulatedTime_ / wallSeconds_ : 0.0);
  } else {
    // A window run: over the whole session, every reset included.
    m.set("real_time_factor", time_.sessionRealTimeFactor());
    m.set("window_fps", time_.sessionFramesPerSecond());
    m.set("longest_frame_ms", 1000.0 * time_.longestFrameSeconds());
    m.set("window_failures", static_cast<double>(failures_));
  }
  m.set("dropped_steps", static_cast<double>(time_.droppedSteps()));
  // Read back from the world: what a key or the panel set reached ODE.
  if (world_) {
    m.set("world_erp", dWorldGetERP(world_));
    m.set("world_cfm", dWorldGetCFM(world_));
  }
  m.set("bodies", bodyCount());
  m.set("disabled_bodies", disabledBodyCount());
  m.set("contacts", contactsLastStep_);
  if (contactChoicesUsed_) {
    m.set("mu", ContactChoices::muMetric(contact_.mu));  // -1: dInfinity (JSON has no infinity)
    m.set("mu_infinite", std::isinf(contact_.mu) ? 1 : 0);
    m.set("max_contacts", contact_.maxContacts);
  }
  m.set("non_finite", blowUpReason_.empty() ? 0 : 1);
  m.set("state_hash", static_cast<double>(stateHash()));
  // Every knob in force at the end, under one prefix (infinity as -1).
  for (const Knob& knob : knobs_) m.set("knob_" + knob.name, knob.metricValue());
  addMetrics(m);
  for (const auto& [name, value] : marks_.entries()) m.set(name, value);
  return m;
}

std::vector<std::pair<std::string, std::string>> AbstractWindow::settingsDescription() const {
  std::vector<std::pair<std::string, std::string>> description{
      {"test", title_},
      {"ode_version", dODE_VERSION},
      {"ode_precision", dCheckConfiguration("ODE_double_precision") ? "double" : "single"},
  };
  // The world settings (step first), what no knob tunes, then every other knob.
  const std::vector<const Knob*> knobs = inReportOrder();
  auto next = knobs.begin();
  for (; next != knobs.end() && (*next)->appliesToWorld; ++next) description.push_back({(*next)->headerKey(), (*next)->headerText()});
  description.push_back({"space", spaceKindName(spaceKind_)});
  description.push_back({"seed", std::to_string(options_.seed)});
  // The run length asked for; the file's last line says whether it was reached.
  description.push_back({"run_seconds_asked", options_.seconds > 0 ? formatValue(options_.seconds)
                                              : options_.headless  ? formatValue(defaultHeadlessSeconds())
                                                                   : std::string("until the window is closed")});
  for (; next != knobs.end(); ++next) description.push_back({(*next)->headerKey(), (*next)->headerText()});
  return description;
}

void AbstractWindow::applySettings(const std::string& change) {
  settings_.applyTo(world_);
  chart_.markChange(simulatedTime_);
  // A replay repeats changes the user has seen already.
  if (!rewind_.replaying()) notify(timeStamp(simulatedTime_) + ": " + change);
  onSettingChanged(change);
}

void AbstractWindow::initialCamera(Camera& camera) const { camera.lookAt({0, 6, 16}, {0, 1, 0}); }

void AbstractWindow::identify(std::string programName, const std::string& title) {
  programName_ = std::move(programName);
  title_ = programName_ + " - " + title;
}

void AbstractWindow::mark(const std::string& label) {
  marks_.set("mark_" + label + "_steps", static_cast<double>(steps_));
  marks_.set("mark_" + label + "_sim_seconds", simulatedTime_);
  marks_.set("mark_" + label + "_hash", static_cast<double>(stateHash()));
}

bool AbstractWindow::plotValue(double& value) const {
  value = contactsLastStep_;
  return true;
}

void AbstractWindow::remove(const AbstractObject* object) {
  removeIf([object](const AbstractObject& o) { return &o == object; });
}

void AbstractWindow::removeIf(const std::function<bool(const AbstractObject&)>& predicate) {
  const AbstractObject* dragged = draggedObject();
  objects_.erase(std::remove_if(objects_.begin(), objects_.end(),
                                [&](const std::unique_ptr<AbstractObject>& o) { return predicate(*o); }),
                 objects_.end());
  // The dragged object's index moves with the removal, or the drag ends.
  drag_.follow(objects_, dragged);
}

}  // namespace odelab
