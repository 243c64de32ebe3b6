#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "Camera.h"
#include "KeyTable.h"
#include "Tuning.h"
#include "SessionTools.h"
#include "WorldRun.h"
#include "world/EngineLink.h"

namespace CLI {
class App;
}

namespace odelab {

namespace world {
class GhostMotion;
}

// The base of every test: the fixed-step loop and the hooks a scene fills
// in. It holds its parts as members, each with one job: WorldRun (world,
// space, objects, counters, blow-up test; creates and destroys the world),
// Tuning (every knob: world settings, contact choices, the scene's),
// SessionTools (clock, rewind, drag, run log, notices), the Camera and the
// KeyTable. Scenes reach them through the few accessors below; the front
// end (utils/render) reads them through run(), tuning() and session(). It
// never calls GL.
class AbstractWindow {
 public:
  explicit AbstractWindow(WorldSettings defaults);
  virtual ~AbstractWindow();
  // The scene's program name ("test4") and title ("Different Weights"),
  // given by its registration (ODELAB_SCENE, tests/scenes/scenes.txt) as it
  // is made, before anything runs.
  void identify(std::string programName, const std::string& title);

  // ---- driven by the runner ----------------------------------------------
  virtual void addOptions(CLI::App& app);  // the scene's own options, before parsing
  void setRunOptions(const RunOptions& options) { options_ = options; }
  const RunOptions& options() const { return options_; }
  // Its files in --out-dir (run log included): --metrics-json and --screenshot may not name them.
  virtual std::vector<std::string> outputFileNames() const { return {programName() + "_run_log.txt"}; }
  virtual void checkOptions() const {}  // after parsing; throws UsageError naming the option
  // A file the scene was made from, as (option, path): odelab's --world.
  // With the options' own inputs (--events, --font), none of the run's
  // writes may name it (cli::refuseInputsAsOutputs).
  void readsFile(std::string option, std::string path) { inputFiles_.emplace_back(std::move(option), std::move(path)); }
  const std::vector<std::pair<std::string, std::string>>& inputFiles() const { return inputFiles_; }
  void initialize(const RunOptions& options);  // builds world and scene, once after parsing
  void reset();     // R: builds the scene again; settings persist
  void shutdown();  // destroys world, space, objects, threading; before dCloseODE()
  // Window path: one frame's real time through the clock, its steps within `steppingBudget`
  // seconds (--record: infinity). A blow-up or ODE error pauses at the last good state.
  void advanceFrame(double elapsedSeconds, double steppingBudget = TimeControl::STEPPING_BUDGET);
  // One step: inputs due, beforeStep, collide, step, measure, check state.
  // Returns false when the state blew up (see blowUpReason()).
  bool stepOnce();
  // Headless: runFor(--seconds or defaultHeadlessSeconds()), then reportHeadless().
  virtual int runHeadless();
  // `seconds` of steps with no input, rewind or plot between them (headless); false if the state blew up.
  bool runFor(double seconds);
  // Ends the output files: "complete: t=..., N steps" or "incomplete: ...; <reason>".
  void endOutputs(const std::string& cutShortBecause);
  int stoppedBySignal();  // after SIGINT/SIGTERM: outputs marked incomplete; 128 + the signal
  Metrics metrics() const;  // the framework's (steps, sim_seconds, ...) then the scene's
  // A compare run (--compare, utils/CompareRun.h) steps several scenes in
  // lockstep, one engine each: `turn` is called before every step runFor()
  // takes and returns when this scene's turn has come; `report` takes the
  // metrics reportHeadless() would print and write (the files are ended and
  // the status is the same). Unset (the default), neither is called.
  struct Lockstep {
    std::function<void()> turn;
    std::function<void(const Metrics&)> report;
  };
  void runInLockstep(Lockstep lockstep) { lockstep_ = std::move(lockstep); }
  // The compare window (utils/CompareLanes.h): every input a person gives
  // this scene that changes the simulation (a recorded key, R included, a
  // panel change, a drag) is passed on to `echo` once applied here, with
  // this scene's step; applyInput() gives it to another scene at its own
  // step. A replay passes nothing on.
  void echoInputs(std::function<void(const TimelineEvent&)> echo) { echo_ = std::move(echo); }
  void applyInput(const TimelineEvent& event);
  // " at t=1.23 s (step 0.001, ERP 0.2, ...)": the end of every ODE error and blow-up message.
  std::string momentAndSettings() const;
  // Kinetic and potential energy of every dynamic body, J (the drag's energy books).
  double bodiesEnergy() const;
  // "key: value" pairs naming every setting in force, for output file headers.
  std::vector<std::pair<std::string, std::string>> settingsDescription() const;

  // ---- the parts, for the front end and checks ------------------------------
  const WorldRun& run() const { return run_; }
  Tuning& tuning() { return tuning_; }
  const Tuning& tuning() const { return tuning_; }
  SessionTools& session() { return session_; }
  const SessionTools& session() const { return session_; }
  Camera& camera() { return camera_; }
  const Camera& camera() const { return camera_; }
  const KeyTable& keys() const { return keys_; }

  // ---- display and input: keys, panel and drag are recorded for rewind -----
  const std::string& title() const { return title_; }  // "test4 - Different Weights"
  const std::string& programName() const { return programName_; }  // "test4"
  std::vector<std::string> hudLines() const;
  // The last lines of hudLines() that come and go: a failure, the notice,
  // ODE's messages. At least one (empty when there is none), so the HUD
  // keeps a row for them and a notice neither pushes the view down as it
  // comes nor lets it jump back as it goes.
  std::vector<std::string> hudPassingLines() const;
  std::vector<std::string> helpLines() const;
  // The scene's headline measurement: the first of its own HUD lines (the
  // compact HUD's), or "" when it has none.
  std::string headline() const;
  virtual SceneBounds bounds() const { return {{0, 0, 0}, 12.0}; }
  // A world file's ghost (world/GhostLaw.h): one body's analytic motion,
  // which the window draws at run().simulatedTime() beside the engines'
  // bodies; null where the scene states none.
  virtual const world::GhostMotion* ghost() const { return nullptr; }
  bool handleKey(SDL_Keycode key, bool shift);  // false if unbound
  // The panel's change of knob `index` (in tuning().knobs()), recorded for rewind.
  void changeKnob(int index, double value);
  void beginDrag(const PickHit& hit, const double target[3]);
  void moveDrag(const double target[3]);
  void endDrag();
  const AbstractObject* draggedObject() const;
  void replayTo(long long step);  // resets and replays up to `step`; leaves it paused
  // A rewind (',') that spreads its replay over frames (AbstractWindowRewind.cpp):
  // rewindTo() starts it or moves its target (presses in a burst coalesce
  // into one target), advanceFrame() replays a frame's budget of steps
  // (at most `rewindStepsPerFrame`, set by a compare window for its
  // slowest engines), and cancelRewind() (Esc, or any recorded input)
  // stops it at the step reached, paused.
  void rewindTo(long long step, const std::string& leftAt);
  bool rewinding() const { return rewindJob_.active; }
  long long rewindTarget() const { return rewindJob_.target; }
  void cancelRewind();
  void setRewindStepsPerFrame(long long steps) { rewindJob_.stepsPerFrame = steps; }
  // The window's stepping time in a frame a rewind was under way (the
  // replay and every engine following it): the longest goes in the metrics
  // as rewind_longest_frame_stepping_ms, a rewind answered frame by frame.
  void noteRewindFrame(double steppingSeconds) {
    rewindJob_.longestFrameSeconds = std::max(rewindJob_.longestFrameSeconds, steppingSeconds);
  }
  void offerSceneSwitch(std::vector<SceneChoice> scenes, int current);  // the launcher's Page Down / Up
  void mark(const std::string& label);  // step, time and state hash as metrics mark_<label>_*
  void applySettings(const std::string& change);  // settings() to the world now; reports `change`
  void setSpaceKind(SpaceKind kind);  // moves every geom into a new space of that kind
  // The world as built and as it is now, as data (doc/world-format.md): --export-world.
  world::World describeWorld();
  // "" where the knob reaches the engine stepping the scene, else why not
  // (KnobReach.h): the HUD and the panel grey its row and say so.
  std::string knobNotReached(const Knob& knob) const;
  // The engine stepping the scene (--engine); inactive for ODE.
  const world::EngineLink& engine() const { return engine_; }

 protected:
  // ---- what scenes read and use --------------------------------------------
  dWorldID world() const { return run_.world(); }
  dSpaceID space() const { return run_.space(); }
  dJointGroupID contactGroup() const { return run_.contactGroup(); }
  SpaceKind spaceKind() const { return run_.spaceKind(); }
  const std::vector<std::unique_ptr<AbstractObject>>& objects() const { return run_.objects(); }
  double simulatedTime() const { return run_.simulatedTime(); }
  long long steps() const { return run_.steps(); }
  double lastStepWallSeconds() const { return run_.lastStepWallSeconds(); }
  int bodyCount() const { return run_.bodyCount(); }
  int disabledBodyCount() const { return run_.disabledBodyCount(); }
  std::mt19937& random() { return run_.random(); }
  void timeSteps() { run_.timeSteps(); }
  const WorldSettings& settings() const { return tuning_.settings(); }
  double contactMu() const { return tuning_.contactMu(); }
  int maxContacts() const { return tuning_.maxContacts(); }
  TimeControl& time() { return session_.time(); }
  const TimeControl& time() const { return session_.time(); }
  void notify(const std::string& message) { session_.notify(message); }

  // ---- hooks for scenes ----------------------------------------------------
  virtual void buildScene() = 0;  // objects and joints, measurement reset; every (re)build
  // World settings beyond WorldSettings (auto-disable...); every (re)build, before buildScene().
  virtual void configureWorld() {}
  // A colliding pair's surface; the default is plain friction with contactMu(),
  // which overrides use too so that --mu, F / G and the panel reach them.
  virtual void setContactSurface(dGeomID o1, dGeomID o2, dSurfaceParameters& surface);
  // Called in a scene's constructor when it has contacts: the knobs mu and
  // max_contacts (--mu, --max-contacts, F / G, the panel's Contacts group).
  void useContactChoices(double defaultMu);
  // Before every step, after recorded inputs and the drag spring, before collision.
  virtual void beforeStep() {}
  virtual void afterStep() {}  // the scene's measurement
  // Scene's own HUD lines (the first is its headline, shown in the compact HUD) and metrics.
  virtual void addHudLines(std::vector<std::string>& lines) const { (void)lines; }
  virtual void addMetrics(Metrics& metrics) const { (void)metrics; }
  virtual void onSettingChanged(const std::string& change) { (void)change; }  // e.g. to log it
  // After a knob changed from its key or the panel (rebuilt already if it rebuilds).
  virtual void onKnobChanged(const Knob& knob) { (void)knob; }
  virtual double defaultHeadlessSeconds() const { return 10.0; }  // without --seconds
  virtual std::string rewindCaveat() const { return {}; }  // why a replay may differ, or ""
  virtual void writeEndLine(const std::string& line) { (void)line; }  // output files' last line
  virtual void initialCamera(Camera& camera) const;
  // The live plot's value after a step and its label with unit (default: contacts).
  virtual bool plotValue(double& value) const;
  virtual std::string plotLabel() const { return "contacts in the last step"; }
  // A scene built from a world file: the file, for another engine to be
  // handed its values rather than ODE's read-back (null: none).
  virtual const world::FileOrigin* fileOrigin() const { return nullptr; }

  // Scene keys; a view key changes only the view and is not recorded. Binding
  // a key twice fails at start-up; rebindKey takes over a shared one (R).
  void bindKey(SDL_Keycode key, std::string keyName, std::string description, std::function<void(int)> action);
  void bindViewKey(SDL_Keycode key, std::string keyName, std::string description, std::function<void(int)> action);
  void rebindKey(SDL_Keycode key, std::string keyName, std::string description, std::function<void(int)> action);
  // A scene value keys change that survives R: rewind restores its start value before replaying.
  template <class T>
  void keepAcrossRewind(T& value) {
    session_.rewind_.keep(value);
  }
  // A knob, declared once (utils/Knob.h): option, keys, panel row, header
  // line, metric and rewind follow. The world settings are declared by the
  // base, the contact choices by useContactChoices().
  Knob& declare(Knob knob);
  // Objects are owned here; scenes keep raw pointers, valid until the next reset.
  template <class T, class... Args>
  T& add(Args&&... args) {
    run_.objects_.push_back(std::make_unique<T>(std::forward<Args>(args)...));
    return static_cast<T&>(*run_.objects_.back());
  }
  void remove(const AbstractObject* object);
  void removeIf(const std::function<bool(const AbstractObject&)>& predicate);
  int reportHeadless();         // prints the metrics, writes --metrics-json; OK or BLEW_UP

 private:
  static void nearCallback(void* data, dGeomID o1, dGeomID o2);
  void createWorld();
  void beginRun();
  void applyEvent(const TimelineEvent& event);
  void recordAndApply(const TimelineEvent& event);
  void logAction(const std::string& text);
  void bindSharedKeys();
  void bindTimeAndViewKeys();
  // Every knob change, from a key ("key"), the panel ("panel") or a replay, ends here.
  void changeKnob(Knob& knob, double value, const char* source);
  void stepKnob(Knob& knob, int direction);
  void recoverFrom(const std::string& failure);
  // The rewind under way: where it goes, the moment it left (for its
  // notice), and the cap on the steps one frame replays (0: the budget only).
  struct RewindJob {
    bool active = false;
    long long target = 0;
    std::string leftAt;
    long long stepsPerFrame = 0;
    double longestFrameSeconds = -1.0;  // -1: no rewind yet
  };
  void beginReplay();                         // the world rebuilt at the run's start, replaying
  void continueRewind(double budgetSeconds);  // a frame's share of the replay
  void endRewind(const std::string& notice);
  std::string rewindLine() const;             // "rewinding... (n of m steps; Esc stops)"
  world::SurfaceOf surfaceOf();
  void startEngine();       // after every (re)build, when --engine names another engine
  bool stepEngine();        // instead of collide and ODE's step; false: the engine's state is not finite
  void engineSettingsChanged();

  WorldRun run_;
  Tuning tuning_;
  SessionTools session_;
  RewindJob rewindJob_;
  std::string programName_;
  std::string title_;
  RunOptions options_;
  Camera camera_;
  KeyTable keys_;
  world::EngineLink engine_;
  Lockstep lockstep_;
  std::function<void(const TimelineEvent&)> echo_;
  std::vector<std::pair<std::string, std::string>> inputFiles_;
};

}  // namespace odelab
