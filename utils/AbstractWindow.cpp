#include "AbstractWindow.h"

#include <ode/version.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>

#include "ExitCodes.h"
#include "MeasurementLog.h"
#include "OdeMessages.h"
#include "SpringDamper.h"

namespace odelab {

namespace {

// The thesis asks dCollide for at least 8 contacts per pair; box-box pairs
// can produce more, so allow a few extra.
constexpr int MAX_CONTACTS = 16;
constexpr double NOTICE_SECONDS = 4.0;
// Rewind marks every quarter simulated second; the live plot samples every
// hundredth. Contact markers are capped so a huge pile cannot flood the renderer.
constexpr double SNAPSHOT_INTERVAL = 0.25;
constexpr double CHART_INTERVAL = 0.01;
constexpr size_t MAX_CONTACT_MARKERS = 4096;
constexpr double MIN_TIME_SCALE = 1.0 / 32.0;
constexpr double MAX_TIME_SCALE = 8.0;
// A blow-up that stays finite (runaway energy): no scene comes near these.
// 1e8 m/s is ten times the fastest launch any scene allows (test10's
// --velocity, at most 1e7 m/s); free fall at 1 g needs 118 days to reach it. There
// is no bound on distance: a body that falls off a platform (test4, test5)
// is 1e8 m down after 75 minutes, which a window session can last.
constexpr double RUNAWAY_SPEED = 1e8;  // m/s
constexpr double RUNAWAY_SPIN = 1e8;   // rad/s

std::string formatValue(double value) {
  std::ostringstream out;
  out << std::setprecision(6) << value;
  return out.str();
}

}  // namespace

const char* spaceKindName(SpaceKind kind) {
  switch (kind) {
    case SpaceKind::Simple: return "simple";
    case SpaceKind::Hash: return "hash";
    case SpaceKind::SweepAndPrune: return "sap";
    case SpaceKind::QuadTree: return "quadtree";
  }
  return "?";
}

bool parseSpaceKind(const std::string& text, SpaceKind& kind) {
  for (SpaceKind candidate : {SpaceKind::Simple, SpaceKind::Hash, SpaceKind::SweepAndPrune, SpaceKind::QuadTree})
    if (text == spaceKindName(candidate)) {
      kind = candidate;
      return true;
    }
  return false;
}

AbstractWindow::AbstractWindow(std::string title, WorldSettings defaults)
    : title_(std::move(title)), settings_(defaults) {
  bindSharedKeys();
  bindTimeAndViewKeys();
}

AbstractWindow::~AbstractWindow() {
  destroyWorld();
  if (runLog_) std::fclose(runLog_);
}

void AbstractWindow::addOptions(CLI::App& app) { (void)app; }

void AbstractWindow::initialize(const RunOptions& options) {
  options_ = options;
  initialCamera(camera_);
  createWorld();
  startEpoch();
}

void AbstractWindow::reset() {
  ++epoch_;
  destroyWorld();
  createWorld();
  startEpoch();
}

// A new run begins: what the timeline replays starts from here.
void AbstractWindow::startEpoch() {
  timeline_.clear();
  epochSettings_ = settings_;
  epochSpace_ = spaceKind_;
  epochStepper_ = stepper_;
  for (auto& kept : keptValues_) kept.save();
}

void AbstractWindow::replayTo(long long step) {
  replaying_ = true;
  settings_ = epochSettings_;
  spaceKind_ = epochSpace_;
  stepper_ = epochStepper_;
  for (auto& kept : keptValues_) kept.restore();
  destroyWorld();
  createWorld();
  timeline_.rewindCursor();
  while (steps_ < step && stepOnce()) {
  }
  replaying_ = false;
  paused_ = true;
}

void AbstractWindow::shutdown() { destroyWorld(); }

void AbstractWindow::createWorld() {
  // Everything random in a run derives from --seed, so a run is reproducible.
  random_.seed(options_.seed);
  dRandSetSeed(options_.seed);
  world_ = dWorldCreate();
  contactGroup_ = dJointGroupCreate(0);
  space_ = nullptr;
  setSpaceKind(spaceKind_);
  settings_.applyTo(world_);
  simulatedTime_ = 0.0;
  steps_ = 0;
  contactsLastStep_ = 0;
  wallSeconds_ = 0.0;
  blowUpReason_.clear();
  clock_.reset();
  dragIndex_ = -1;
  contactMarkers_.clear();
  chart_.clear();
  chart_.label = plotLabel();
  nextChartTime_ = 0.0;
  nextSnapshotTime_ = SNAPSHOT_INTERVAL;
  configureWorld();
  buildScene();
}

void AbstractWindow::destroyWorld() {
  objects_.clear();
  if (contactGroup_) dJointGroupDestroy(contactGroup_);
  if (space_) dSpaceDestroy(space_);
  if (world_) dWorldDestroy(world_);
  contactGroup_ = nullptr;
  space_ = nullptr;
  world_ = nullptr;
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
    while (dSpaceGetNumGeoms(space_) > 0) {
      dGeomID geom = dSpaceGetGeom(space_, 0);
      dSpaceRemove(space_, geom);
      dSpaceAdd(next, geom);
    }
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
  const int count = dCollide(o1, o2, MAX_CONTACTS, &contact[0].geom, sizeof(dContact));
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
  surface.mu = dInfinity;
}

bool AbstractWindow::stepOnce() {
  const auto start = std::chrono::steady_clock::now();
  timeline_.applyDue(steps_, [this](const TimelineEvent& event) { applyEvent(event); });
  if (dragIndex_ >= 0)
    if (const dBodyID body = objects_[dragIndex_]->getBody())
      DragSpring::apply(body, dragGrab_, dragTarget_, settings_.gravity);
  contactsThisStep_ = 0;
  if (viewFlags_.contacts) contactMarkers_.clear();
  try {
    dSpaceCollide(space_, this, &AbstractWindow::nearCallback);
    if (settings_.solver == Solver::QuickStep)
      dWorldQuickStep(world_, settings_.step);
    else
      dWorldStep(world_, settings_.step);
  } catch (const OdeError& error) {
    // ODE's own checks often see a blow-up before stateProblem() does (a NaN
    // quaternion fails dxNormalize4): report it with the time and settings.
    throw OdeError(std::string(error.what()) + " at t=" + formatValue(simulatedTime_) + " s" + settingsInForce());
  }
  dJointGroupEmpty(contactGroup_);
  contactsLastStep_ = contactsThisStep_;
  simulatedTime_ += settings_.step;
  ++steps_;
  lastStepWallSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  afterStep();
  timeline_.extendHorizon(steps_);
  if (simulatedTime_ >= nextSnapshotTime_) {
    timeline_.markSnapshot(steps_);
    nextSnapshotTime_ += SNAPSHOT_INTERVAL;
  }
  if (simulatedTime_ >= nextChartTime_) {
    double value;
    if (plotValue(value)) chart_.add(simulatedTime_, value);
    nextChartTime_ += CHART_INTERVAL;
  }
  const std::string problem = stateProblem();
  if (!problem.empty()) {
    std::ostringstream reason;
    reason << "simulation blew up: " << problem << " at t=" << formatValue(simulatedTime_) << " s"
           << settingsInForce();
    blowUpReason_ = reason.str();
    return false;
  }
  return true;
}

// " (step 0.001, ERP 0.2, CFM 1e-06, solver quick, 20 iterations)"
std::string AbstractWindow::settingsInForce() const {
  std::ostringstream text;
  text << " (step " << formatValue(settings_.step) << ", ERP " << formatValue(settings_.erp) << ", CFM "
       << formatValue(settings_.cfm) << ", solver " << solverName(settings_.solver) << ", " << settings_.iterations
       << " iterations)";
  return text.str();
}

std::string AbstractWindow::stateProblem() const {
  auto length = [](const dReal* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); };
  for (const auto& object : objects_) {
    const dBodyID body = object->getBody();
    if (!body) continue;
    const dReal* position = dBodyGetPosition(body);
    const dReal* velocity = dBodyGetLinearVel(body);
    const dReal* spin = dBodyGetAngularVel(body);
    for (const dReal* v : {position, velocity, spin})
      if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) return "non-finite body state";
    // Finite but absurd: energy has run away (no scene comes near these).
    if (length(velocity) > RUNAWAY_SPEED)
      return "runaway energy: a body moves at " + formatValue(length(velocity)) + " m/s";
    if (length(spin) > RUNAWAY_SPIN)
      return "runaway energy: a body spins at " + formatValue(length(spin)) + " rad/s";
  }
  return {};
}

void AbstractWindow::advanceFrame(double elapsedSeconds) {
  wallSeconds_ += elapsedSeconds;
  const int stepsNow = paused_ ? 0 : clock_.advance(elapsedSeconds, settings_.step, timeScale_);
  const double simBefore = simulatedTime_;
  for (int i = 0; i < stepsNow; ++i) {
    if (!stepOnce()) {
      const std::string reason = blowUpReason_;
      reset();
      notify(reason + "; scene reset");
      return;
    }
  }
  // Real-time factor over roughly the last second of frames.
  rateWindowReal_ += elapsedSeconds;
  rateWindowSim_ += simulatedTime_ - simBefore;
  if (rateWindowReal_ >= 1.0) {
    realTimeFactor_ = rateWindowSim_ / rateWindowReal_;
    rateWindowReal_ = rateWindowSim_ = 0.0;
  }
  if (options_.seconds > 0 && simulatedTime_ >= options_.seconds) quitRequested_ = true;
}

int AbstractWindow::runHeadless() {
  runFor(options_.seconds > 0 ? options_.seconds : defaultHeadlessSeconds());
  return reportHeadless();
}

bool AbstractWindow::runFor(double seconds) {
  const long long total = steps_ + std::llround(seconds / settings_.step);
  const auto start = std::chrono::steady_clock::now();
  bool finite = blowUpReason_.empty();
  while (steps_ < total && finite) finite = stepOnce();
  wallSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  realTimeFactor_ = wallSeconds_ > 0 ? simulatedTime_ / wallSeconds_ : 0.0;
  return finite;
}

int AbstractWindow::reportHeadless() {
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

std::uint64_t AbstractWindow::stateHash() const {
  // FNV-1a over the exact bytes of every body's position, orientation and
  // velocities, in creation order; cut to 52 bits so JSON's doubles hold it.
  std::uint64_t hash = 1469598103934665603ull;
  auto mix = [&hash](const dReal* values, int count) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(values);
    for (size_t i = 0; i < count * sizeof(dReal); ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  };
  for (const auto& object : objects_) {
    const dBodyID body = object->getBody();
    if (!body) continue;
    mix(dBodyGetPosition(body), 3);
    mix(dBodyGetQuaternion(body), 4);
    mix(dBodyGetLinearVel(body), 3);
    mix(dBodyGetAngularVel(body), 3);
  }
  return hash & ((1ull << 52) - 1);
}

namespace {
// Distinct bodies: the geoms of a composite body share one.
std::set<dBodyID> bodiesOf(const std::vector<std::unique_ptr<AbstractObject>>& objects) {
  std::set<dBodyID> bodies;
  for (const auto& object : objects)
    if (const dBodyID body = object->getBody()) bodies.insert(body);
  return bodies;
}
}  // namespace

int AbstractWindow::bodyCount() const { return static_cast<int>(bodiesOf(objects_).size()); }

int AbstractWindow::disabledBodyCount() const {
  int count = 0;
  for (const dBodyID body : bodiesOf(objects_))
    if (!dBodyIsEnabled(body)) ++count;
  return count;
}

Metrics AbstractWindow::metrics() const {
  Metrics m;
  m.set("steps", static_cast<double>(steps_));
  m.set("sim_seconds", simulatedTime_);
  m.set("wall_seconds", wallSeconds_);
  m.set("real_time_factor", realTimeFactor_);
  m.set("bodies", bodyCount());
  m.set("disabled_bodies", disabledBodyCount());
  m.set("contacts", contactsLastStep_);
  m.set("non_finite", blowUpReason_.empty() ? 0 : 1);
  m.set("state_hash", static_cast<double>(stateHash()));
  addMetrics(m);
  for (const auto& [name, value] : marks_.entries()) m.set(name, value);
  return m;
}

std::vector<std::pair<std::string, std::string>> AbstractWindow::settingsDescription() const {
  return {
      {"test", title_},
      {"ode_version", dODE_VERSION},
      {"ode_precision", dCheckConfiguration("ODE_double_precision") ? "double" : "single"},
      {"step_seconds", formatValue(settings_.step)},
      {"erp", formatValue(settings_.erp)},
      {"cfm", formatValue(settings_.cfm)},
      {"solver", solverName(settings_.solver) == std::string("quick") ? "quick (dWorldQuickStep)"
                                                                       : "step (dWorldStep)"},
      {"iterations", std::to_string(settings_.iterations)},
      {"sor_w", formatValue(settings_.sor)},
      {"gravity", formatValue(settings_.gravity)},
      {"space", spaceKindName(spaceKind_)},
      {"seed", std::to_string(options_.seed)},
  };
}

void AbstractWindow::applySettings(const std::string& change) {
  settings_.applyTo(world_);
  lastChange_ = change;
  std::ostringstream line;
  line << "t=" << formatValue(simulatedTime_) << " s: " << change;
  notify(line.str());
  onSettingChanged(change);
}

void AbstractWindow::notify(const std::string& message) {
  std::cerr << message << '\n';
  notice_ = message;
  noticeUntil_ = wallSeconds_ + NOTICE_SECONDS;
}

void AbstractWindow::initialCamera(Camera& camera) const { camera.lookAt({0, 6, 16}, {0, 1, 0}); }

void AbstractWindow::bindViewKey(SDL_Keycode key, std::string keyName, std::string description,
                                 std::function<void(int)> action) {
  bindKey(key, std::move(keyName), std::move(description), std::move(action));
  keyBindings_.back().recorded = false;
}

void AbstractWindow::bindKey(SDL_Keycode key, std::string keyName, std::string description,
                             std::function<void(int)> action) {
  // A scene binding replaces a shared one on the same key.
  keyBindings_.erase(std::remove_if(keyBindings_.begin(), keyBindings_.end(),
                                    [key](const KeyBinding& b) { return b.key == key; }),
                     keyBindings_.end());
  keyBindings_.push_back({key, std::move(keyName), std::move(description), std::move(action)});
}

bool AbstractWindow::handleKey(SDL_Keycode key, bool shift) {
  for (const auto& binding : keyBindings_) {
    if (binding.key != key) continue;
    if (!binding.recorded || replaying_) {
      binding.action(shift ? -1 : +1);
      return true;
    }
    // A recorded key goes on the timeline, unless it began a new run (R).
    const long long epochBefore = epoch_;
    lastChange_.clear();
    binding.action(shift ? -1 : +1);
    if (epoch_ == epochBefore) {
      TimelineEvent event;
      event.step = steps_;
      event.kind = TimelineEvent::Kind::Key;
      event.key = key;
      event.shift = shift;
      recordEvent(event);
    }
    logAction((shift ? "Shift+" : "") + binding.keyName + ": " +
              (lastChange_.empty() ? binding.description : lastChange_));
    return true;
  }
  return false;
}

void AbstractWindow::runBinding(SDL_Keycode key, bool shift) {
  for (const auto& binding : keyBindings_)
    if (binding.key == key) {
      binding.action(shift ? -1 : +1);
      return;
    }
}

void AbstractWindow::recordEvent(TimelineEvent event) {
  if (!replaying_) timeline_.record(event);
}

void AbstractWindow::applyEvent(const TimelineEvent& event) {
  switch (event.kind) {
    case TimelineEvent::Kind::Key:
      runBinding(event.key, event.shift);
      break;
    case TimelineEvent::Kind::Drag:
      dragIndex_ = event.objectIndex < static_cast<int>(objects_.size()) ? event.objectIndex : -1;
      std::copy(event.grab, event.grab + 3, dragGrab_);
      std::copy(event.target, event.target + 3, dragTarget_);
      break;
    case TimelineEvent::Kind::Release:
      dragIndex_ = -1;
      break;
  }
}

void AbstractWindow::logAction(const std::string& text) {
  // The run log exists for windowed sessions, where a person presses keys.
  if (options_.headless || runLogFailed_) return;
  if (!runLog_) {
    const std::string path = joinPath(options_.outDir, programName() + "_run_log.txt");
    runLog_ = std::fopen(path.c_str(), "w");
    if (!runLog_) {
      runLogFailed_ = true;
      notify("cannot write the run log '" + path + "'");
      return;
    }
    std::fprintf(runLog_, "# %s: inputs that changed the simulation, with their simulated time\n", title_.c_str());
  }
  std::fprintf(runLog_, "t=%.6g s (step %lld): %s\n", simulatedTime_, steps_, text.c_str());
  std::fflush(runLog_);
}

void AbstractWindow::stepSetting(const char* what, const std::function<void()>& change) {
  const WorldSettings before = settings_;
  change();
  std::ostringstream text;
  auto describe = [&](double from, double to) { text << what << ' ' << formatValue(from) << " -> " << formatValue(to); };
  const std::string name = what;
  if (name == "ERP") describe(before.erp, settings_.erp);
  else if (name == "CFM") describe(before.cfm, settings_.cfm);
  else if (name == "iterations") describe(before.iterations, settings_.iterations);
  else if (name == "SOR w") describe(before.sor, settings_.sor);
  else if (name == "step") describe(before.step, settings_.step);
  else if (name == "solver") text << "solver " << solverName(before.solver) << " -> " << solverName(settings_.solver);
  applySettings(text.str());
}

void AbstractWindow::bindSharedKeys() {
  bindKey(SDLK_ESCAPE, "Esc", "quit", [this](int) { quitRequested_ = true; });
  bindKey(SDLK_r, "R", "reset the scene to its initial state", [this](int) {
    reset();
    notify("scene reset");
  });
  bindKey(SDLK_F1, "F1", "HUD on / off", [this](int) { hudVisible_ = !hudVisible_; });
  bindKey(SDLK_F2, "F2", "choose the increment used by F3 / F4 (1e-6 ... 0.1)", [this](int d) {
    stepper_.cycleIncrement(d);
    applySettings("F2 increment " + formatValue(stepper_.increment()));
  });
  bindKey(SDLK_F3, "F3", "ERP up by the increment (Shift: down), within [0, 1]",
          [this](int d) { stepSetting("ERP", [&] { stepper_.stepErp(settings_, d); }); });
  bindKey(SDLK_F4, "F4", "CFM up by the increment (Shift: down), within [0, 1]",
          [this](int d) { stepSetting("CFM", [&] { stepper_.stepCfm(settings_, d); }); });
  bindKey(SDLK_F6, "F6", "QuickStep iterations up (Shift: down): 1, 2, 3, 5, 8, 10, 15, 20, 30, 50 ... 1000",
          [this](int d) { stepSetting("iterations", [&] { ParameterStepper::stepIterations(settings_, d); }); });
  bindKey(SDLK_F7, "F7", "SOR relaxation w up by 0.05 (Shift: down), within [0.05, 1.95]",
          [this](int d) { stepSetting("SOR w", [&] { ParameterStepper::stepSor(settings_, d); }); });
  bindKey(SDLK_F8, "F8", "step size up (Shift: down): 1e-5, 2e-5, 5e-5 ... 0.1 s",
          [this](int d) { stepSetting("step", [&] { ParameterStepper::stepStepSize(settings_, d); }); });
  bindKey(SDLK_F9, "F9", "switch solver: dWorldQuickStep / dWorldStep", [this](int) {
    stepSetting("solver", [&] {
      settings_.solver = settings_.solver == Solver::QuickStep ? Solver::WorldStep : Solver::QuickStep;
    });
  });
}

PickHit AbstractWindow::pickAt(const double origin[3], const double direction[3]) const {
  return pickObject(objects_, origin, direction);
}

void AbstractWindow::beginDrag(const PickHit& hit, const double target[3]) {
  if (hit.objectIndex < 0 || hit.objectIndex >= static_cast<int>(objects_.size())) return;
  const dBodyID body = objects_[hit.objectIndex]->getBody();
  if (!body) return;
  dVector3 local;
  dBodyGetPosRelPoint(body, hit.point[0], hit.point[1], hit.point[2], local);
  TimelineEvent event;
  event.step = steps_;
  event.kind = TimelineEvent::Kind::Drag;
  event.objectIndex = hit.objectIndex;
  std::copy(local, local + 3, event.grab);
  std::copy(target, target + 3, event.target);
  applyEvent(event);
  recordEvent(event);
  marks_.set("drag_start_distance", DragSpring::distance(body, dragGrab_, dragTarget_));
  logAction("drag " + std::to_string(hit.objectIndex));
}

void AbstractWindow::moveDrag(const double target[3]) {
  if (dragIndex_ < 0) return;
  TimelineEvent event;
  event.step = steps_;
  event.kind = TimelineEvent::Kind::Drag;
  event.objectIndex = dragIndex_;
  std::copy(dragGrab_, dragGrab_ + 3, event.grab);
  std::copy(target, target + 3, event.target);
  applyEvent(event);
  recordEvent(event);
  // The gap the spring now has to close (the renderer's beginDrag targets
  // the grabbed point itself, so the gap opens with the first move).
  if (const dBodyID body = objects_[dragIndex_]->getBody())
    marks_.set("drag_start_distance", DragSpring::distance(body, dragGrab_, dragTarget_));
}

void AbstractWindow::endDrag() {
  if (dragIndex_ < 0) return;
  if (const dBodyID body = objects_[dragIndex_]->getBody())
    marks_.set("drag_end_distance", DragSpring::distance(body, dragGrab_, dragTarget_));
  TimelineEvent event;
  event.step = steps_;
  event.kind = TimelineEvent::Kind::Release;
  applyEvent(event);
  recordEvent(event);
  logAction("release");
}

const AbstractObject* AbstractWindow::draggedObject() const {
  return dragIndex_ >= 0 ? objects_[dragIndex_].get() : nullptr;
}

bool AbstractWindow::takeScreenshotRequest() {
  const bool requested = screenshotRequested_;
  screenshotRequested_ = false;
  return requested;
}

std::string AbstractWindow::programName() const { return title_.substr(0, title_.find(' ')); }

void AbstractWindow::mark(const std::string& label) {
  marks_.set("mark_" + label + "_steps", static_cast<double>(steps_));
  marks_.set("mark_" + label + "_sim_seconds", simulatedTime_);
  marks_.set("mark_" + label + "_hash", static_cast<double>(stateHash()));
}

bool AbstractWindow::plotValue(double& value) const {
  value = contactsLastStep_;
  return true;
}

void AbstractWindow::bindTimeAndViewKeys() {
  bindViewKey(SDLK_p, "P", "pause / resume", [this](int) { paused_ = !paused_; });
  bindViewKey(SDLK_o, "O", "advance exactly one step (pauses first)", [this](int) {
    paused_ = true;
    if (!stepOnce()) {
      const std::string reason = blowUpReason_;
      reset();
      notify(reason + "; scene reset");
    }
  });
  bindViewKey(SDLK_MINUS, "-", "slower: halve the time scale (down to 1/32)",
              [this](int) { timeScale_ = std::max(MIN_TIME_SCALE, timeScale_ * 0.5); });
  bindViewKey(SDLK_EQUALS, "=", "faster: double the time scale (up to 8x, as far as the machine keeps up)",
              [this](int) { timeScale_ = std::min(MAX_TIME_SCALE, timeScale_ * 2.0); });
  bindViewKey(SDLK_COMMA, ",", "rewind to the previous snapshot (every 0.25 s of simulated time) and pause", [this](int) {
    const long long target = std::max(0LL, timeline_.previousSnapshot(steps_));
    replayTo(target);
    notify("rewound to t=" + formatValue(simulatedTime_) + " s");
  });
  bindViewKey(SDLK_PERIOD, ".", "forward to the next snapshot, replaying what was recorded, and pause", [this](int) {
    const long long target = timeline_.nextSnapshot(steps_);
    paused_ = true;
    if (target < 0) {
      notify("no later snapshot: press P to run on");
      return;
    }
    while (steps_ < target && stepOnce()) {
    }
    notify("forward to t=" + formatValue(simulatedTime_) + " s");
  });
  bindViewKey(SDLK_h, "H", "help: this key list on / off", [this](int) { viewFlags_.help = !viewFlags_.help; });
  bindViewKey(SDLK_l, "L", "live plot of the scene's measurement on / off",
              [this](int) { viewFlags_.plot = !viewFlags_.plot; });
  bindViewKey(SDLK_c, "C", "contact points and normals on / off", [this](int) {
    viewFlags_.contacts = !viewFlags_.contacts;
    contactMarkers_.clear();
  });
  bindViewKey(SDLK_j, "J", "joint anchors and axes on / off", [this](int) { viewFlags_.joints = !viewFlags_.joints; });
  bindViewKey(SDLK_x, "X", "bounding boxes on / off", [this](int) { viewFlags_.boxes = !viewFlags_.boxes; });
  bindViewKey(SDLK_v, "V", "wireframe on / off", [this](int) { viewFlags_.wireframe = !viewFlags_.wireframe; });
  bindViewKey(SDLK_F12, "F12", "save a screenshot (PNG named with the test and the simulated time) in --out-dir",
              [this](int) { screenshotRequested_ = true; });
}

std::vector<std::string> AbstractWindow::helpLines() const {
  std::vector<std::string> lines{
      "left mouse   on a body: drag it with a spring; elsewhere: toggle mouse-look",
      "W/S/A/D      move the camera forward / back / left / right along the view",
      "Shift        reverses every F-key",
  };
  for (const auto& binding : keyBindings_) {
    std::string name = binding.keyName;
    name.resize(std::max<size_t>(name.size(), 12), ' ');
    lines.push_back(name + " " + binding.description);
  }
  return lines;
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
  dragIndex_ = -1;
  for (size_t i = 0; dragged && i < objects_.size(); ++i)
    if (objects_[i].get() == dragged) dragIndex_ = static_cast<int>(i);
}

// ERP and CFM as the spring and damper they mean at this step, and the ERP
// and CFM that would keep that spring at the next step size (F8).
std::string AbstractWindow::springLine() const {
  const SpringDamper spring = springDamperOf(settings_.erp, settings_.cfm, settings_.step);
  if (spring.rigid) return "constraints rigid (CFM 0): no spring; ERP corrects " + formatValue(settings_.erp) +
                           " of the error per step";
  WorldSettings next = settings_;
  ParameterStepper::stepStepSize(next, +1);
  const ErpCfm keep = erpCfmFor(spring, next.step);
  std::ostringstream s;
  s << "spring kp " << formatValue(spring.kp) << " N/m, damper kd " << formatValue(spring.kd)
    << " N s/m; at step " << formatValue(next.step) << " keep them with ERP " << formatValue(keep.erp) << ", CFM "
    << formatValue(keep.cfm);
  return s.str();
}

std::vector<std::string> AbstractWindow::hudLines() const {
  std::vector<std::string> lines;
  std::ostringstream s;
  s << title_;
  lines.push_back(s.str());
  s.str("");
  s << "ERP " << formatValue(settings_.erp) << "   CFM " << formatValue(settings_.cfm) << "   step "
    << formatValue(settings_.step) << " s   F2 increment " << formatValue(stepper_.increment());
  lines.push_back(s.str());
  s.str("");
  s << "solver " << (settings_.solver == Solver::QuickStep ? "dWorldQuickStep" : "dWorldStep") << "   iterations "
    << settings_.iterations << "   SOR w " << formatValue(settings_.sor) << "   space " << spaceKindName(spaceKind_);
  lines.push_back(s.str());
  s.str("");
  s << std::fixed << std::setprecision(0) << "FPS " << framesPerSecond_ << std::setprecision(2) << "   sim "
    << simulatedTime_ << " s   real-time x" << realTimeFactor_;
  lines.push_back(s.str());
  s.str("");
  s << "bodies " << bodyCount() << " (" << disabledBodyCount() << " disabled)   contacts " << contactsLastStep_;
  lines.push_back(s.str());
  s.str("");
  s << (paused_ ? "PAUSED (P runs, O steps)" : "running") << "   time scale x" << formatValue(timeScale_)
    << "   rewind , .  (" << timeline_.snapshotCount() << " snapshots)   H help";
  lines.push_back(s.str());
  lines.push_back(springLine());
  if (const AbstractObject* object = draggedObject()) {
    const dReal* v = dBodyGetLinearVel(object->getBody());
    s.str("");
    s << "dragging object #" << dragIndex_ << " (" << (object->shape() == Shape::Box ? "box" : "sphere") << ", "
      << formatValue(object->mass()) << " kg), speed "
      << formatValue(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])) << " m/s";
    lines.push_back(s.str());
  }
  addHudLines(lines);
  if (!notice_.empty() && wallSeconds_ < noticeUntil_) lines.push_back(notice_);
  for (const auto& message : OdeMessages::recent()) lines.push_back(message);
  return lines;
}

}  // namespace odelab
