#pragma once

#include <ode/ode.h>

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "AbstractObject.h"
#include "BodyStateWatch.h"
#include "Camera.h"
#include "ContactChoices.h"
#include "DebugMarkers.h"
#include "KeyTable.h"
#include "Knob.h"
#include "Metrics.h"
#include "MouseDrag.h"
#include "Rewind.h"
#include "RunLog.h"
#include "RunOptions.h"
#include "SceneParameters.h"
#include "SceneView.h"
#include "SettingsTable.h"
#include "SpaceKind.h"
#include "StripChart.h"
#include "TimeControl.h"

namespace CLI {
class App;
}

namespace odelab {

// The base of every test: owns the ODE world, the collision space, the
// contact group and the fixed-step loop, and composes the parts with rules
// of their own: TimeControl (clock, pause, scale, budget), Rewind (run start,
// timeline), MouseDrag, KeyTable, SceneParameters, RunLog. It never calls
// GL: the window front end (utils/render) reads poses and HUD lines from it,
// and headless runs drive it directly. doc/framework.md draws who owns what.
class AbstractWindow {
 public:
  AbstractWindow(std::string title, WorldSettings defaults);
  virtual ~AbstractWindow();
  AbstractWindow(const AbstractWindow&) = delete;
  AbstractWindow& operator=(const AbstractWindow&) = delete;

  // ---- driven by the runner ----------------------------------------------
  virtual void addOptions(CLI::App& app);  // the scene's own options, before parsing
  // --mu and --max-contacts, for scenes that called useContactChoices().
  void addContactOptions(CLI::App& app);
  // Every declared knob; the runner adds their options (utils/CommandLine.h).
  std::deque<Knob>& knobs() { return knobs_; }
  const std::deque<Knob>& knobs() const { return knobs_; }
  void setRunOptions(const RunOptions& options) { options_ = options; }
  // Its files in --out-dir (run log included): --metrics-json and --screenshot may not name them.
  virtual std::vector<std::string> outputFileNames() const { return {programName() + "_run_log.txt"}; }
  // Checks between options after parsing; throw UsageError naming the option.
  virtual void checkOptions() const {}
  // Builds the world and the scene. Call once after options are parsed.
  void initialize(const RunOptions& options);
  void reset();     // R: builds the scene again; settings persist
  void shutdown();  // destroys world, space, objects, threading; before dCloseODE()
  // Window path: one frame's elapsed real time through the clock, and its
  // steps within `steppingBudget` seconds (--record passes infinity). A
  // blow-up or an ODE error pauses at the last good state (see failure()).
  void advanceFrame(double elapsedSeconds, double steppingBudget = TimeControl::STEPPING_BUDGET);
  // One step: inputs due, beforeStep, collide, step, measure, check state.
  // Returns false when the state blew up (see blowUpReason()).
  bool stepOnce();
  // Headless path: runFor(--seconds or defaultHeadlessSeconds()), then
  // reportHeadless(). Scenes with their own experiment override it.
  virtual int runHeadless();
  // Ends the output files: "complete: t=..., N steps" or "incomplete: ...; <reason>".
  void endOutputs(const std::string& cutShortBecause);
  // After SIGINT/SIGTERM: marks the outputs incomplete; returns 128 + the signal.
  int stoppedBySignal();

  // ---- read and driven by the front end -------------------------------------
  const std::string& title() const { return title_; }
  std::string programName() const;  // "test0" from "test0 - Box & Sphere"
  const std::vector<std::unique_ptr<AbstractObject>>& objects() const { return objects_; }
  std::vector<std::string> hudLines() const;
  HudMode hudMode() const { return hudMode_; }
  const KeyTable& keys() const { return keys_; }
  bool handleKey(SDL_Keycode key, bool shift);  // false if unbound
  std::vector<std::string> helpLines() const;
  bool quitRequested() const { return quitRequested_; }
  void requestQuit() { quitRequested_ = true; }
  // The launcher's window: Page Down / Page Up end this scene's frame loop
  // asking for the next / previous scene of the registry (switchRequest()).
  void offerSceneSwitch(const std::string& sceneList);
  int switchRequest() const { return switchRequest_; }
  Camera& camera() { return camera_; }
  const Camera& camera() const { return camera_; }
  bool mouseLook() const { return mouseLook_; }
  void toggleMouseLook() { mouseLook_ = !mouseLook_; }
  virtual SceneBounds bounds() const { return {{0, 0, 0}, 12.0}; }
  const RunOptions& runOptions() const { return options_; }
  TimeControl& time() { return time_; }
  const TimeControl& time() const { return time_; }
  const Timeline& timeline() const { return rewind_.timeline(); }
  // Rebuilds the state at `step` by resetting and replaying; leaves it paused.
  void replayTo(long long step);
  const ViewFlags& viewFlags() const { return viewFlags_; }
  const std::vector<ContactMarker>& contactMarkers() const { return contactMarkers_; }
  std::vector<JointMarker> jointMarkers() const { return collectJointMarkers(objects_); }
  const StripChart& chart() const { return chart_; }
  bool takeScreenshotRequest();  // true once per F12 press
  // Records step, simulated time and state hash as metrics mark_<label>_*.
  void mark(const std::string& label);
  // The last blow-up or ODE error, kept on screen until dismissed (Enter).
  const std::string& failure() const { return failure_; }
  void dismissFailure() { failure_.clear(); }
  // The notice of the last few seconds ("" when none).
  std::string notice() const;

  // Mouse drag: grab the hit object at the hit point, pull it toward a target.
  PickHit pickAt(const double origin[3], const double direction[3]) const;
  void beginDrag(const PickHit& hit, const double target[3]);
  void moveDrag(const double target[3]);
  void endDrag();
  bool dragging() const { return drag_.active(); }
  const AbstractObject* draggedObject() const;
  const double* dragTarget() const { return drag_.target(); }

  // The control panel: the same path as the keys (clamped, recorded, logged).
  void changeSetting(SettingId id, double value);
  void changeParameter(int index, double value);
  const SceneParameters& parameters() const { return parameters_; }
  double f2Increment() const { return stepper_.increment(); }

  // ---- state, for scenes and tests -----------------------------------------
  dWorldID world() const { return world_; }
  dSpaceID space() const { return space_; }
  dJointGroupID contactGroup() const { return contactGroup_; }
  WorldSettings& settings() { return settings_; }
  const WorldSettings& settings() const { return settings_; }
  double simulatedTime() const { return simulatedTime_; }
  long long steps() const { return steps_; }
  int contactsLastStep() const { return contactsLastStep_; }
  // Real seconds spent in dSpaceCollide since the program started (the window's frame profile).
  double collideWallSeconds() const { return collideWallSeconds_; }
  double lastStepWallSeconds() const { return lastStepWallSeconds_; }  // 0 unless the scene called timeSteps()
  const std::string& blowUpReason() const { return blowUpReason_; }
  // " at t=1.23 s (step 0.001, ERP 0.2, ...)": what every ODE error and
  // blow-up message ends with, on the main thread or in a pool thread.
  std::string momentAndSettings() const;
  int bodyCount() const;
  int disabledBodyCount() const;
  // A hash of every body's exact state (the determinism check).
  std::uint64_t stateHash() const;
  // Every metric: the framework's (steps, sim_seconds, ...) then the scene's.
  Metrics metrics() const;
  // "key: value" pairs naming every setting in force, for output file headers.
  std::vector<std::pair<std::string, std::string>> settingsDescription() const;
  // Applies settings() to the world now (after an edit) and reports `change`.
  void applySettings(const std::string& change);
  // Replaces the collision space by one of another kind, moving every geom.
  void setSpaceKind(SpaceKind kind);
  SpaceKind spaceKind() const { return spaceKind_; }

 protected:
  // ---- hooks for scenes ----------------------------------------------------
  // Create objects and joints; reset measurement state. Called on every (re)build.
  virtual void buildScene() = 0;
  // World settings beyond WorldSettings (auto-disable, surface layer...);
  // every (re)build, before buildScene().
  virtual void configureWorld() {}
  // Contact surface for a colliding pair; the default is plain friction (mu dInfinity).
  // Overrides take mu from contactMu() so --mu, F / G and the panel reach them.
  virtual void setContactSurface(dGeomID o1, dGeomID o2, dSurfaceParameters& surface);
  // A scene with contacts calls it in its constructor: --mu, --max-contacts, F / G, panel, metrics.
  void useContactChoices(double defaultMu);
  double contactMu() const { return contact_.mu; }
  int maxContacts() const { return contact_.contactLimit(); }
  // Before every step, after recorded inputs and the drag spring are
  // applied and before collision: forces, swept tests, scripted changes.
  virtual void beforeStep() {}
  // After every step: the scene's measurement.
  virtual void afterStep() {}
  // Scene's own HUD lines (the first is its headline, shown in the compact HUD) and metrics.
  virtual void addHudLines(std::vector<std::string>& lines) const { (void)lines; }
  virtual void addMetrics(Metrics& metrics) const { (void)metrics; }
  // After any setting change (keys, panel), e.g. to log it in an output file.
  virtual void onSettingChanged(const std::string& change) { (void)change; }
  // After a knob changed from its key or the panel (a knob that rebuilds
  // the scene has been rebuilt already).
  virtual void onKnobChanged(const Knob& knob) { (void)knob; }
  virtual double defaultHeadlessSeconds() const { return 10.0; }  // without --seconds
  // Why a rewind (a replay) may not match the run, or "": shown on rewinding.
  virtual std::string rewindCaveat() const { return {}; }
  // Scenes with output files write `line` as their last line (MeasurementLog::finish).
  virtual void writeEndLine(const std::string& line) { (void)line; }
  virtual void initialCamera(Camera& camera) const;
  // The live plot's value after a step and its label with unit; the default
  // plots the contacts of the last step.
  virtual bool plotValue(double& value) const;
  virtual std::string plotLabel() const { return "contacts in the last step"; }

  // Scene keys; a view key changes only the view and is not recorded.
  void bindKey(SDL_Keycode key, std::string keyName, std::string description,
               std::function<void(int direction)> action);
  void bindViewKey(SDL_Keycode key, std::string keyName, std::string description,
                   std::function<void(int direction)> action);
  // A scene value that keys change and that survives R: rewind restores it
  // to its value at the start of the run before replaying.
  template <class T>
  void keepAcrossRewind(T& value) {
    rewind_.keep(value);
  }
  // A scene's knob, declared once (utils/Knob.h): its option, key, panel
  // row and rewind follow from the declaration. Returns the stored knob.
  Knob& declare(Knob knob);
  // A scene key that takes over a shared one (R): binding a key twice otherwise fails at start-up.
  void rebindKey(SDL_Keycode key, std::string keyName, std::string description,
                 std::function<void(int direction)> action);

  // Objects are owned here; scenes keep raw pointers, valid until the next reset.
  template <class T, class... Args>
  T& add(Args&&... args) {
    auto object = std::make_unique<T>(std::forward<Args>(args)...);
    T& reference = *object;
    objects_.push_back(std::move(object));
    return reference;
  }
  void remove(const AbstractObject* object);
  void removeIf(const std::function<bool(const AbstractObject&)>& predicate);

  bool runFor(double seconds);  // false if the state blew up
  int reportHeadless();         // prints the metrics, writes --metrics-json; OK or BLEW_UP

  std::mt19937& random() { return random_; }
  const RunOptions& options() const { return options_; }
  // Measure every step's wall time (lastStepWallSeconds()); off by default.
  void timeSteps() { timeSteps_ = true; }
  // Prints a line on stderr and keeps it for the HUD for a few seconds.
  void notify(const std::string& message);

 private:
  static void nearCallback(void* data, dGeomID o1, dGeomID o2);
  void createWorld();
  void destroyWorld();
  void beginRun();
  void applyEvent(const TimelineEvent& event);
  void recordAndApply(const TimelineEvent& event);
  void logAction(const std::string& text);
  void bindSharedKeys();
  void bindTimeAndViewKeys();
  void bindSetting(const SettingSpec& spec);
  void changeKnob(Knob& knob, double value, const std::string& source);
  static bool settingKey(SDL_Keycode key);
  void reportSetting(const SettingChange& change);
  void recoverFrom(const std::string& failure);
  bool stateSuspicious() const;  // the cheap test behind stateProblem()
  std::string stateProblem() const;
  std::string settingsInForce() const;

  std::string title_;
  WorldSettings settings_;
  RunOptions options_;
  ParameterStepper stepper_;
  Camera camera_;
  KeyTable keys_;
  TimeControl time_;
  Rewind rewind_;
  MouseDrag drag_;
  SceneParameters parameters_;
  std::deque<Knob> knobs_;
  std::vector<Knob*> panelKnobs_;  // parameters_'s rows, in order
  RunLog runLog_;
  std::vector<std::unique_ptr<AbstractObject>> objects_;
  BodyStateWatch watch_;  // stateSuspicious()'s view of the bodies
  std::mt19937 random_;

  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contactGroup_ = nullptr;
  SpaceKind spaceKind_ = SpaceKind::Simple;
  dThreadingImplementationID stepThreading_ = nullptr;  // the world's; see createWorld()

  double simulatedTime_ = 0.0;
  long long steps_ = 0;
  int contactsLastStep_ = 0;
  int contactsThisStep_ = 0;
  double lastStepWallSeconds_ = 0.0;
  double collideWallSeconds_ = 0.0;
  bool profileCollision_ = false;
  bool timeSteps_ = false;
  bool unattended_ = false;  // inside runFor(): no input, rewind or plot, so stepOnce() skips them
  double wallSeconds_ = 0.0;  // real time spent in this run (headless) or its frames (window)
  std::string blowUpReason_;
  HudMode hudMode_ = HudMode::Compact;
  bool quitRequested_ = false;
  int switchRequest_ = 0;  // +1 next scene, -1 previous, 0 none
  bool mouseLook_ = false;
  std::string notice_, failure_;
  long long failures_ = 0;  // blow-ups and ODE errors a window recovered from
  double noticeUntil_ = 0.0;  // in real seconds of window time

  ViewFlags viewFlags_;
  std::vector<ContactMarker> contactMarkers_;
  StripChart chart_;
  double nextChartTime_ = 0.0;
  bool screenshotRequested_ = false;
  Metrics marks_;
  ContactChoices contact_{dInfinity};
  bool contactChoicesUsed_ = false;
};

}  // namespace odelab
