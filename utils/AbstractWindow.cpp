#include "AbstractWindow.h"

#include <ode/version.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <unordered_set>

#include "ExitCodes.h"
#include "MechanicalEnergy.h"
#include "FormatValue.h"
#include "LineText.h"
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

AbstractWindow::AbstractWindow(WorldSettings defaults) : tuning_(defaults) {
  bindSharedKeys();
  for (Knob& knob : worldKnobs(tuning_.settings_, tuning_.increment_)) declare(std::move(knob));
  bindTimeAndViewKeys();
}

AbstractWindow::~AbstractWindow() { shutdown(); }

void AbstractWindow::addOptions(CLI::App& app) { (void)app; }

void AbstractWindow::initialize(const RunOptions& options) {
  options_ = options;
  session_.time_.setMaximumFrameTime(options.maxFrameTime);
  session_.hudMode_ = options.hud;
  session_.runLog_.setTarget(joinPath(options.outDir, programName() + "_run_log.txt"), title_);
  initialCamera(camera_);
  createWorld();
  beginRun();
}

void AbstractWindow::reset() {
  rewindJob_.active = false;  // R wins over a rewind under way
  session_.rewind_.setReplaying(false);
  session_.rewind_.newEpoch();
  session_.dragEnergy_.clear();
  session_.failure_.clear();
  run_.destroy();
  createWorld();
  beginRun();
}

// A new run begins: what the timeline replays starts from here.
void AbstractWindow::beginRun() { session_.rewind_.begin({tuning_.settings_, run_.spaceKind_, tuning_.increment_}); }

void AbstractWindow::replayTo(long long step) {
  rewindJob_.active = false;
  beginReplay();
  while (run_.steps_ < step && stepOnce()) {
  }
  session_.rewind_.setReplaying(false);
  session_.time_.setPaused(true);
  const std::string caveat = rewindCaveat();
  if (!caveat.empty()) notify("warning: " + caveat);
}

void AbstractWindow::shutdown() {
  run_.destroy();
  run_.freeThreading();
}

void AbstractWindow::createWorld() {
  // The scene's output files are opened (and a previous run's replaced)
  // only once its engine has built it too: an engine that refuses the
  // scene leaves them as they were (StreamedFile::Hold).
  StreamedFile::Hold outputsHeld;
  run_.create(options_.seed);
  setSpaceKind(run_.spaceKind_);
  tuning_.settings_.applyTo(run_.world_);
  session_.time_.resetClock();
  session_.drag_.release();
  session_.contactMarkers_.clear();
  session_.chart_.clear();
  session_.chart_.label = plotLabel();
  session_.nextChartTime_ = 0.0;
  session_.rewind_.worldRebuilt();
  configureWorld();
  buildScene();
  startEngine();
  outputsHeld.release();
}

void AbstractWindow::setSpaceKind(SpaceKind kind) { run_.setSpaceKind(kind, bounds()); }

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
    dJointID joint = dJointCreateContact(self->run_.world_, self->run_.contactGroup_, &contact[i]);
    dJointAttach(joint, b1, b2);
  }
  self->run_.contactsThisStep_ += count;
  if (self->session_.viewFlags_.contacts)
    for (int i = 0; i < count && self->session_.contactMarkers_.size() < MAX_CONTACT_MARKERS; ++i) {
      const dContactGeom& g = contact[i].geom;
      self->session_.contactMarkers_.push_back({{float(g.pos[0]), float(g.pos[1]), float(g.pos[2])},
                                       {float(g.normal[0]), float(g.normal[1]), float(g.normal[2])},
                                       float(g.depth)});
    }
}

void AbstractWindow::setContactSurface(dGeomID, dGeomID, dSurfaceParameters& surface) {
  surface.mode = 0;
  surface.mu = contactMu();
}

void AbstractWindow::useContactChoices(double defaultMu) {
  tuning_.contactChoicesUsed_ = true;
  tuning_.contact_.mu = defaultMu;
  for (Knob& knob : tuning_.contact_.knobs()) declare(std::move(knob));
}

bool AbstractWindow::stepOnce() {
  // The clock only for scenes that measure a step's wall time (test5): two
  // clock reads a step are a tenth of a one-ball scene's framework cost.
  const auto start = run_.timeSteps_ ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
  // Inputs, the drag, contact markers, rewind marks and the live plot: none
  // can come or be seen inside runFor(), which skips their cost.
  const bool attended = !run_.unattended_;
  // The drag's energy books (DragEnergy) are kept for the run as it goes,
  // not for a replay after a rewind.
  const bool booked = attended && !session_.rewind_.replaying();
  int pulledIndex = -1;
  if (attended) {
    session_.rewind_.timeline().applyDue(run_.steps_, [this](const TimelineEvent& event) { applyEvent(event); });
    double force[3], point[3];
    const double energyBefore =
        booked && session_.drag_.active() && !session_.dragEnergy_.watching() ? bodiesEnergy() : 0.0;
    if (session_.drag_.pull(run_.objects_, tuning_.settings_.gravity, force, point)) {
      pulledIndex = session_.drag_.index();
      if (booked) session_.dragEnergy_.pulled(energyBefore, force, point);
    }
    if (session_.viewFlags_.contacts) session_.contactMarkers_.clear();
  }
  run_.contactsThisStep_ = 0;
  beforeStep();
  if (engine_.active()) {
    // Another engine steps the world; ODE's bodies take its states.
    if (!stepEngine()) return false;
  } else {
    try {
      // ODE's own collision and step calls are timed in every run (two clock
      // reads, 40 ns each here): the engine_wall_seconds set beside another
      // engine's (--engine), the engines' cost compared like with like.
      const auto collideStart = std::chrono::steady_clock::now();
      dSpaceCollide(run_.space_, this, &AbstractWindow::nearCallback);
      if (run_.profileCollision_)
        run_.collideWallSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - collideStart).count();
      if (tuning_.settings_.solver == Solver::QuickStep)
        dWorldQuickStep(run_.world_, tuning_.settings_.step);
      else
        dWorldStep(run_.world_, tuning_.settings_.step);
      run_.engineWallSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - collideStart).count();
    } catch (const OdeError& error) {
      // ODE's own checks often see a blow-up before run_.stateProblem() does (a NaN
      // quaternion fails dxNormalize4): report it with the time and settings.
      throw OdeError(std::string(error.what()) + momentAndSettings());
    }
    dJointGroupEmpty(run_.contactGroup_);
  }
  run_.contactsLastStep_ = run_.contactsThisStep_;
  run_.simulatedTime_ += tuning_.settings_.step;
  ++run_.steps_;
  // On another engine, what the engine's own calls took (not the edits and states passed to it).
  if (run_.timeSteps_)
    run_.lastStepWallSeconds_ = engine_.active() ? run_.engineStepWallSeconds_
                                                 : std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  afterStep();
  if (booked && pulledIndex >= 0) {
    double point[3];
    if (session_.drag_.grabbedPoint(run_.objects_, pulledIndex, point)) session_.dragEnergy_.moved(point);
  } else if (booked && session_.dragEnergy_.watching()) {
    session_.dragEnergy_.released(bodiesEnergy());
  }
  if (attended) {
    session_.rewind_.afterStep(run_.simulatedTime_, run_.steps_);
    if (run_.simulatedTime_ >= session_.nextChartTime_) {
      double value;
      if (plotValue(value)) session_.chart_.add(run_.simulatedTime_, value);
      session_.nextChartTime_ += CHART_INTERVAL;
    }
  }
  // Every step: a few multiplications per body; the message only when one looks wrong.
  if (!run_.stateSuspicious()) return true;
  const std::string problem = run_.stateProblem();
  if (problem.empty()) return true;
  run_.blowUpReason_ = "simulation blew up: " + problem + momentAndSettings();
  return false;
}

double AbstractWindow::bodiesEnergy() const {
  // Objects attached into one body (test2's rod and bob) share it: counted once.
  std::unordered_set<dBodyID> counted;
  double energy = 0.0;
  for (const auto& object : run_.objects_)
    if (const dBodyID body = object->getBody())
      if (!dBodyIsKinematic(body) && counted.insert(body).second) energy += mechanicalEnergy(body, run_.world_);
  return energy;
}

std::string AbstractWindow::momentAndSettings() const {
  return " at t=" + formatValue(run_.simulatedTime_) + " s" + tuning_.settingsInForce();
}

void AbstractWindow::advanceFrame(double elapsedSeconds, double steppingBudget) {
  run_.profileCollision_ = true;  // only a window advances by frames
  run_.wallSeconds_ += elapsedSeconds;
  if (rewindJob_.active) {
    continueRewind(steppingBudget);
    return;
  }
  const int stepsNow = session_.time_.stepsFor(elapsedSeconds, tuning_.settings_.step);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < stepsNow; ++i) {
    // A run given --seconds ends on the step a headless run ends on, not
    // wherever the frame that crossed it ends: the last picture, the output
    // files and the metrics are those of that moment on any machine.
    if (runLengthReached(options_.seconds, run_.simulatedTime_, tuning_.settings_.step)) break;
    if (i > 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > steppingBudget) {
      session_.time_.dropSteps(stepsNow - i);
      break;
    }
    std::string failure;
    try {
      if (!stepOnce()) failure = run_.blowUpReason_;
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
      run_.stepThreading_ = nullptr;
    }
    if (!failure.empty()) {
      recoverFrom(failure);
      return;
    }
  }
  if (runLengthReached(options_.seconds, run_.simulatedTime_, tuning_.settings_.step)) session_.quitRequested_ = true;
}

// A blow-up or an ODE error in a window: the run is replayed to the step
// before the failure and paused there, with the message on screen until it
// is dismissed; the timeline stays, so , rewinds further and R starts over.
void AbstractWindow::recoverFrom(const std::string& failure) {
  ++session_.failures_;
  const long long lastGood = run_.steps_ - 1;
  replayTo(std::max(0LL, lastGood));
  session_.failure_ = failure + "; paused at the last good state, t=" + formatValue(run_.simulatedTime_) +
             " s (Enter dismisses, , rewinds, R resets)";
  notify(session_.failure_);
}

int AbstractWindow::runHeadless() {
  runFor(options_.seconds > 0 ? options_.seconds : defaultHeadlessSeconds());
  return reportHeadless();
}

bool AbstractWindow::runFor(double seconds) {
  const long long total = run_.steps_ + std::llround(seconds / tuning_.settings_.step);
  const auto start = std::chrono::steady_clock::now();
  bool finite = run_.blowUpReason_.empty();
  {
    // Set for the loop only, and cleared even when a step throws.
    struct Unattended {
      bool& flag;
      ~Unattended() { flag = false; }
    } unattended{run_.unattended_ = true};
    if (lockstep_.turn)  // a compare run: each scene's step in turn (utils/CompareRun.cpp)
      while (run_.steps_ < total && finite && stopSignal() == 0) {
        lockstep_.turn();
        finite = stepOnce();
      }
    else
      while (run_.steps_ < total && finite && stopSignal() == 0) finite = stepOnce();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run_.wallSeconds_ += wall;
  session_.time_.addRun(wall, seconds);
  return finite;
}

int AbstractWindow::reportHeadless() {
  if (stopSignal() != 0) return stoppedBySignal();
  endOutputs(run_.blowUpReason_);
  const Metrics result = metrics();
  const int status = run_.blowUpReason_.empty() ? exit_code::OK
                     : run_.engineFailed_        ? exit_code::ENGINE_FAILED
                                                 : exit_code::BLEW_UP;
  if (lockstep_.report) {  // a compare run prints and writes every engine's together
    lockstep_.report(result);
    return status;
  }
  std::cout << title_ << ": " << formatValue(run_.simulatedTime_) << " simulated seconds\n";
  result.print(std::cout);
  if (!options_.metricsJson.empty()) result.writeJsonAtomically(options_.metricsJson);
  if (!run_.blowUpReason_.empty()) std::cerr << "error: " << run_.blowUpReason_ << '\n';
  return status;
}

void AbstractWindow::endOutputs(const std::string& cutShortBecause) {
  const std::string where = "t=" + formatValue(run_.simulatedTime_) + " s, " + std::to_string(run_.steps_) + " steps";
  writeEndLine(cutShortBecause.empty() ? "complete: " + where : "incomplete: " + where + "; " + cutShortBecause);
}

// SIGINT or SIGTERM stopped the run: the files say so, no metrics are
// written as if the run were whole, and the status is the shell's 128 + N.
int AbstractWindow::stoppedBySignal() {
  endOutputs(std::string("stopped by ") + stopSignalName());
  std::cerr << "error: stopped by " << stopSignalName() << " at t=" << formatValue(run_.simulatedTime_)
            << " s; no metrics written\n";
  return 128 + stopSignal();
}

Metrics AbstractWindow::metrics() const {
  Metrics m;
  m.set("steps", static_cast<double>(run_.steps_));
  m.set("sim_seconds", run_.simulatedTime_);
  m.set("wall_seconds", run_.wallSeconds_);
  if (options_.headless) {
    m.set("real_time_factor", run_.wallSeconds_ > 0 ? run_.simulatedTime_ / run_.wallSeconds_ : 0.0);
  } else {
    // A window run: over the whole session, every reset included.
    m.set("real_time_factor", session_.time_.sessionRealTimeFactor());
    m.set("window_fps", session_.time_.sessionFramesPerSecond());
    m.set("longest_frame_ms", 1000.0 * session_.time_.longestFrameSeconds());
    m.set("window_failures", static_cast<double>(session_.failures_));
  }
  m.set("dropped_steps", static_cast<double>(session_.time_.droppedSteps()));
  // Read back from the world: what a key or the panel set reached ODE.
  if (run_.world_) {
    m.set("world_erp", dWorldGetERP(run_.world_));
    m.set("world_cfm", dWorldGetCFM(run_.world_));
  }
  m.set("bodies", bodyCount());
  m.set("disabled_bodies", disabledBodyCount());
  m.set("contacts", run_.contactsLastStep_);
  if (tuning_.contactChoicesUsed_) {
    m.set("mu", ContactChoices::muMetric(tuning_.contact_.mu));  // -1: dInfinity (JSON has no infinity)
    m.set("mu_infinite", std::isinf(tuning_.contact_.mu) ? 1 : 0);
    m.set("max_contacts", tuning_.contact_.maxContacts);
  }
  // A blow-up is a state not finite; an engine that failed is not one.
  m.set("non_finite", run_.blowUpReason_.empty() || run_.engineFailed_ ? 0 : 1);
  m.set("state_hash", static_cast<double>(run_.stateHash()));
  // The engine's own collision and step calls (ODE's, or --engine's without
  // the edits and states passed to it): the cost compared like with like.
  m.set("engine_wall_seconds", engine_.active() ? engine_.engineWallSeconds() : run_.engineWallSeconds_);
  // The link's own time outside those calls; ODE steps in this process with no link: 0.
  m.set("link_wall_seconds", engine_.active() ? engine_.linkWallSeconds() : 0.0);
  if (engine_.active()) {
    m.set("engine_cpu_seconds", engine_.engineCpuSeconds());
    m.set("translation_note_count", static_cast<double>(engine_.translationNotes().size()));
    m.set("engine_failed", run_.engineFailed_ ? 1 : 0);  // 1: status 7, the engine and not its physics
    m.setTexts("engine", {engine_.engineName(), options_.engineBest ? "best" : "default"});
    m.setTexts("translation_notes", engine_.translationNotes());
  }
  // Every knob in force at the end, under one prefix (infinity as -1).
  for (const Knob& knob : tuning_.knobs_) m.set("knob_" + knob.name, knob.metricValue());
  addMetrics(m);
  for (const auto& [name, value] : session_.marks_.entries()) m.set(name, value);
  session_.dragEnergy_.write(m);
  if (rewindJob_.longestFrameSeconds >= 0.0)
    m.set("rewind_longest_frame_stepping_ms", 1000.0 * rewindJob_.longestFrameSeconds);
  return m;
}

std::vector<std::pair<std::string, std::string>> AbstractWindow::settingsDescription() const {
  std::vector<std::pair<std::string, std::string>> description{
      {"test", title_},
      {"ode_version", dODE_VERSION},
      {"ode_precision", dCheckConfiguration("ODE_double_precision") ? "double" : "single"},
  };
  // The world settings (step first), what no knob tunes, then every other knob.
  const std::vector<const Knob*> knobs = tuning_.inReportOrder();
  auto next = knobs.begin();
  for (; next != knobs.end() && (*next)->appliesToWorld; ++next) description.push_back({(*next)->headerKey(), (*next)->headerText()});
  // Where a scene tunes the collision space with a knob (test5), the knob's line says it.
  const bool spaceKnob = std::any_of(knobs.begin(), knobs.end(), [](const Knob* k) { return k->headerKey() == "space"; });
  if (!spaceKnob) description.push_back({"space", spaceKindName(run_.spaceKind_)});
  description.push_back({"seed", std::to_string(options_.seed)});
  // On another engine, which: a file says what made its figures. (The
  // header is written as the scene is built, before the engine has said
  // what it could not express: those notes go to stderr and the metrics.)
  if (options_.engine != "ode")
    description.push_back({"engine", options_.engine + (options_.engineBest ? " (best settings)" : " (default settings)")});
  // The run length asked for; the file's last line says whether it was reached.
  description.push_back({"run_seconds_asked", options_.seconds > 0 ? formatValue(options_.seconds)
                                              : options_.headless  ? formatValue(defaultHeadlessSeconds())
                                                                   : std::string("until the window is closed")});
  for (; next != knobs.end(); ++next) description.push_back({(*next)->headerKey(), (*next)->headerText()});
  return description;
}

void AbstractWindow::applySettings(const std::string& change) {
  tuning_.settings_.applyTo(run_.world_);
  session_.chart_.markChange(run_.simulatedTime_);
  // A replay repeats changes the user has seen already.
  if (!session_.rewind_.replaying()) notify(timeStamp(run_.simulatedTime_) + ": " + change);
  onSettingChanged(change);
}

void AbstractWindow::initialCamera(Camera& camera) const { camera.lookAt({0, 6, 16}, {0, 1, 0}); }

void AbstractWindow::identify(std::string programName, const std::string& title) {
  programName_ = std::move(programName);
  // A world file's title is the user's text: one line wherever the title goes (HUD, outputs, stdout).
  title_ = programName_ + " - " + lineText(title);
}

void AbstractWindow::mark(const std::string& label) {
  session_.marks_.set("mark_" + label + "_steps", static_cast<double>(run_.steps_));
  session_.marks_.set("mark_" + label + "_sim_seconds", run_.simulatedTime_);
  session_.marks_.set("mark_" + label + "_hash", static_cast<double>(run_.stateHash()));
}

bool AbstractWindow::plotValue(double& value) const {
  value = run_.contactsLastStep_;
  return true;
}

void AbstractWindow::remove(const AbstractObject* object) {
  removeIf([object](const AbstractObject& o) { return &o == object; });
}

void AbstractWindow::removeIf(const std::function<bool(const AbstractObject&)>& predicate) {
  const AbstractObject* dragged = draggedObject();
  run_.objects_.erase(std::remove_if(run_.objects_.begin(), run_.objects_.end(),
                                [&](const std::unique_ptr<AbstractObject>& o) { return predicate(*o); }),
                 run_.objects_.end());
  // The dragged object's index moves with the removal, or the drag ends.
  session_.drag_.follow(run_.objects_, dragged);
}

}  // namespace odelab
