#pragma once

#include <SDL2/SDL_keycode.h>
#include <ode/ode.h>

#include <chrono>
#include <cstdio>
#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "AbstractObject.h"
#include "Camera.h"
#include "DebugMarkers.h"
#include "DragSpring.h"
#include "FixedStepClock.h"
#include "Metrics.h"
#include "StripChart.h"
#include "Timeline.h"
#include "WorldSettings.h"

namespace CLI {
class App;
}

namespace odelab {

enum class SpaceKind { Simple, Hash, SweepAndPrune, QuadTree };
const char* spaceKindName(SpaceKind kind);  // "simple", "hash", "sap", "quadtree"
bool parseSpaceKind(const std::string& text, SpaceKind& kind);

// Options shared by every test program, filled from the command line.
struct RunOptions {
  bool headless = false;
  double seconds = 0.0;  // headless: run length (0 = the scene's default); window: quit after (0 = never)
  unsigned seed = 1;
  std::string outDir = ".";
  std::string metricsJson;
  std::string screenshot;  // window: save a PNG after `frames` frames and exit
  int frames = 60;
  std::string shaderDir;
  std::string fontPath;
  int width = 1280;
  int height = 720;
  std::string recordDir;   // window: save every frame as a numbered PNG here
  std::string eventsFile;  // window: scripted input (see doc/manual.md, "Scripted input")
};

// One key of the scene: the same table drives dispatch, --help and doc/.
struct KeyBinding {
  SDL_Keycode key;
  std::string keyName;
  std::string description;
  std::function<void(int direction)> action;  // direction is -1 with Shift, else +1
  // Whether the key changes the simulation: such presses are recorded on the
  // timeline (rewind replays them) and in the run log. View keys are not.
  bool recorded = true;
};

// What the debug drawing and overlays show; toggled by view keys.
struct ViewFlags {
  bool contacts = false;   // C: contact points and normals
  bool joints = false;     // J: joint anchors and axes
  bool boxes = false;      // X: axis-aligned bounding boxes
  bool wireframe = false;  // V: wireframe
  bool plot = false;       // L: live plot of the scene's measurement
  bool help = false;       // H: the key list
};

// A sphere around what the scene shows, used to fit the shadow map.
struct SceneBounds {
  double centre[3];
  double radius;
};

// The base of every test: owns the ODE world, the collision space, the contact
// group and the thesis's fixed-step loop; the camera, the HUD text and the key
// bindings. It never calls GL: the window front end (utils/render) reads poses
// and HUD lines from it, and headless runs drive it directly.
class AbstractWindow {
 public:
  AbstractWindow(std::string title, WorldSettings defaults);
  virtual ~AbstractWindow();
  AbstractWindow(const AbstractWindow&) = delete;
  AbstractWindow& operator=(const AbstractWindow&) = delete;

  // ---- driven by the runner ----------------------------------------------
  // Scene-specific command-line options; called before parsing.
  virtual void addOptions(CLI::App& app);
  // The parsed common options; options() returns them from here on.
  void setRunOptions(const RunOptions& options) { options_ = options; }
  // Checks between options after parsing (options() is set); throw
  // UsageError (CommandLine.h) naming the option. Runs before anything is written.
  virtual void checkOptions() const {}
  // Builds the world and the scene. Call once after options are parsed.
  void initialize(const RunOptions& options);
  // R: tears everything down and builds the scene again; settings persist.
  void reset();
  // Destroys the world, space, every object and the world's threading
  // implementation; call before dCloseODE().
  void shutdown();
  // A frame's steps may take this much real time; what is left of them is
  // dropped, so that whatever the settings (step 1e-5 at 8x with 1000
  // iterations asks for 8000 costly steps a frame) the window goes on
  // answering input. The simulation then runs slower than real time, which
  // the HUD's real-time factor shows; dropped_steps counts them.
  static constexpr double FRAME_STEPPING_BUDGET = 0.05;
  // Window path: feeds one frame's elapsed real time through the clock and
  // runs the resulting steps, within `steppingBudget` seconds of real time
  // (--record passes infinity: each recorded frame is exactly its share of
  // simulated time). A blow-up or an ODE error in a step is reported and
  // the scene reset: the session goes on.
  void advanceFrame(double elapsedSeconds, double steppingBudget = FRAME_STEPPING_BUDGET);
  // One step: collide, step, empty the contact group, measure, check state.
  // Returns false when the state became non-finite (see blowUpReason()).
  bool stepOnce();
  // Headless path: runs for options.seconds (or defaultHeadlessSeconds()),
  // then reportHeadless(). Scenes with their own experiment (several
  // launches, a search) override it with runFor() calls and end with
  // reportHeadless().
  virtual int runHeadless();

  // ---- read by the front end -----------------------------------------------
  const std::string& title() const { return title_; }
  const std::vector<std::unique_ptr<AbstractObject>>& objects() const { return objects_; }
  std::vector<std::string> hudLines() const;
  const std::vector<KeyBinding>& keyBindings() const { return keyBindings_; }
  // Finds the key in the table and runs it; false if unbound.
  bool handleKey(SDL_Keycode key, bool shift);
  bool hudVisible() const { return hudVisible_; }
  bool quitRequested() const { return quitRequested_; }
  void requestQuit() { quitRequested_ = true; }
  Camera& camera() { return camera_; }
  const Camera& camera() const { return camera_; }
  bool mouseLook() const { return mouseLook_; }
  void toggleMouseLook() { mouseLook_ = !mouseLook_; }
  virtual SceneBounds bounds() const { return {{0, 0, 0}, 12.0}; }
  void setFramesPerSecond(double fps) { framesPerSecond_ = fps; }
  const RunOptions& runOptions() const { return options_; }

  // ---- time: P pause, O one step, - / = slower / faster, , / . rewind ----
  bool paused() const { return paused_; }
  double timeScale() const { return timeScale_; }
  const Timeline& timeline() const { return timeline_; }
  // Rebuilds the state at `step` of this run by resetting and replaying the
  // recorded inputs; leaves the simulation paused there.
  void replayTo(long long step);

  // ---- mouse drag ---------------------------------------------------------
  PickHit pickAt(const double origin[3], const double direction[3]) const;
  // Grabs the hit object at the hit point and pulls it toward `target`.
  void beginDrag(const PickHit& hit, const double target[3]);
  void moveDrag(const double target[3]);
  void endDrag();
  bool dragging() const { return dragIndex_ >= 0; }
  const AbstractObject* draggedObject() const;
  const double* dragTarget() const { return dragTarget_; }

  // ---- debug drawing and overlays -------------------------------------------
  const ViewFlags& viewFlags() const { return viewFlags_; }
  const std::vector<ContactMarker>& contactMarkers() const { return contactMarkers_; }
  std::vector<JointMarker> jointMarkers() const { return collectJointMarkers(objects_); }
  const StripChart& chart() const { return chart_; }
  // The key list: mouse and camera keys, then every binding of the table.
  std::vector<std::string> helpLines() const;
  // True once per F12 press.
  bool takeScreenshotRequest();
  // "test0" from "test0 - Box & Sphere": the stem of file names.
  std::string programName() const;

  // ---- scripted checks --------------------------------------------------------
  // Records the current step, simulated time and state hash as metrics
  // mark_<label>_steps, mark_<label>_sim_seconds, mark_<label>_hash.
  void mark(const std::string& label);

  // ---- state, for scenes and tests -----------------------------------------
  dWorldID world() const { return world_; }
  dSpaceID space() const { return space_; }
  dJointGroupID contactGroup() const { return contactGroup_; }
  WorldSettings& settings() { return settings_; }
  const WorldSettings& settings() const { return settings_; }
  double simulatedTime() const { return simulatedTime_; }
  long long steps() const { return steps_; }
  int contactsLastStep() const { return contactsLastStep_; }
  double lastStepWallSeconds() const { return lastStepWallSeconds_; }
  const std::string& blowUpReason() const { return blowUpReason_; }
  int bodyCount() const;
  // A hash of every body's exact state: equal for two runs that followed the
  // same trajectory bit for bit (the determinism check).
  std::uint64_t stateHash() const;
  int disabledBodyCount() const;
  // Every metric: the framework's (steps, sim_seconds, ...) then the scene's.
  Metrics metrics() const;
  // "key: value" pairs naming every setting in force, for output file headers.
  std::vector<std::pair<std::string, std::string>> settingsDescription() const;
  // Applies settings() to the world now (after an edit) and records the change.
  void applySettings(const std::string& change);
  // Replaces the collision space by one of another kind, moving every geom.
  void setSpaceKind(SpaceKind kind);
  SpaceKind spaceKind() const { return spaceKind_; }

 protected:
  // ---- hooks for scenes ----------------------------------------------------
  // Create objects and joints; reset measurement state. Called on every (re)build.
  virtual void buildScene() = 0;
  // World settings beyond WorldSettings (auto-disable, max angular speed,
  // surface layer...). Called on every (re)build, before buildScene().
  virtual void configureWorld() {}
  // Contact surface for a colliding pair; the default is plain friction (mu dInfinity).
  virtual void setContactSurface(dGeomID o1, dGeomID o2, dSurfaceParameters& surface);
  // Before every step, after recorded inputs and the drag spring are
  // applied and before collision: forces, swept tests, scripted changes.
  virtual void beforeStep() {}
  // After every step: the scene's measurement.
  virtual void afterStep() {}
  // Scene's own HUD lines and metrics.
  virtual void addHudLines(std::vector<std::string>& lines) const { (void)lines; }
  virtual void addMetrics(Metrics& metrics) const { (void)metrics; }
  // Called after any setting change (F-keys), e.g. to log it in an output file.
  virtual void onSettingChanged(const std::string& change) { (void)change; }
  // Headless run length when --seconds is not given.
  virtual double defaultHeadlessSeconds() const { return 10.0; }
  // Where the camera starts.
  virtual void initialCamera(Camera& camera) const;
  // The live plot's value after a step and its label with unit; the default
  // plots the contacts of the last step.
  virtual bool plotValue(double& value) const;
  virtual std::string plotLabel() const { return "contacts in the last step"; }

  // Scene keys. B / N / F5 are bound through these when the scene supports them.
  void bindKey(SDL_Keycode key, std::string keyName, std::string description,
               std::function<void(int direction)> action);
  // A key that changes only the view (not recorded on the timeline).
  void bindViewKey(SDL_Keycode key, std::string keyName, std::string description,
                   std::function<void(int direction)> action);
  // A scene value that keys change and that survives R (a launch velocity, a
  // friction coefficient): rewind restores it to its value at the start of
  // the run before replaying the recorded key presses.
  template <class T>
  void keepAcrossRewind(T& value) {
    auto saved = std::make_shared<T>(value);
    keptValues_.push_back({[&value, saved] { *saved = value; }, [&value, saved] { value = *saved; }});
  }

  // Objects are owned here; scenes keep raw pointers, valid until the next reset.
  template <class T, class... Args>
  T& add(Args&&... args) {
    auto object = std::make_unique<T>(std::forward<Args>(args)...);
    T& reference = *object;
    objects_.push_back(std::move(object));
    return reference;
  }
  void remove(const AbstractObject* object);
  // Removes every object for which `predicate` is true.
  void removeIf(const std::function<bool(const AbstractObject&)>& predicate);

  // Steps for `seconds` of simulated time (wall time is added to the run's
  // total); false if the state blew up (blowUpReason() says how).
  bool runFor(double seconds);
  // Prints the metrics, writes --metrics-json, and returns OK or BLEW_UP.
  int reportHeadless();

  std::mt19937& random() { return random_; }
  const RunOptions& options() const { return options_; }
  // Prints a line on stderr and keeps it for the HUD for a few seconds.
  void notify(const std::string& message);

 private:
  static void nearCallback(void* data, dGeomID o1, dGeomID o2);
  void createWorld();
  void destroyWorld();
  void startEpoch();
  void applyEvent(const TimelineEvent& event);
  void runBinding(SDL_Keycode key, bool shift);
  void recordEvent(TimelineEvent event);
  void logAction(const std::string& text);
  void bindSharedKeys();
  void bindTimeAndViewKeys();
  std::string springLine() const;
  void stepSetting(const char* what, const std::function<void()>& change);
  // Empty while every body is finite and below the runaway speed and spin;
  // otherwise what is wrong ("non-finite body state", "runaway energy: ...").
  std::string stateProblem() const;
  // The settings a blow-up or an ODE error is reported with.
  std::string settingsInForce() const;

  std::string title_;
  WorldSettings settings_;
  RunOptions options_;
  ParameterStepper stepper_;
  FixedStepClock clock_;
  Camera camera_;
  std::vector<KeyBinding> keyBindings_;
  std::vector<std::unique_ptr<AbstractObject>> objects_;
  std::mt19937 random_;

  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contactGroup_ = nullptr;
  SpaceKind spaceKind_ = SpaceKind::Simple;

  double simulatedTime_ = 0.0;
  long long steps_ = 0;
  int contactsLastStep_ = 0;
  int contactsThisStep_ = 0;
  double lastStepWallSeconds_ = 0.0;
  double wallSeconds_ = 0.0;  // real time spent in the run (headless) or frames (window)
  std::string blowUpReason_;
  bool hudVisible_ = true;
  bool quitRequested_ = false;
  bool mouseLook_ = false;
  double framesPerSecond_ = 0.0;
  double realTimeFactor_ = 0.0;
  long long droppedSteps_ = 0;  // steps a frame's stepping budget left out
  dThreadingImplementationID stepThreading_ = nullptr;  // the world's; see createWorld()
  double rateWindowReal_ = 0.0, rateWindowSim_ = 0.0;
  std::string notice_;
  double noticeUntil_ = 0.0;  // in real seconds of window time

  // Time control and the timeline of recorded inputs.
  bool paused_ = false;
  double timeScale_ = 1.0;
  Timeline timeline_;
  bool replaying_ = false;
  long long epoch_ = 0;  // counts resets that start a new run (R, not replays)
  WorldSettings epochSettings_;
  SpaceKind epochSpace_ = SpaceKind::Simple;
  ParameterStepper epochStepper_;
  struct KeptValue {
    std::function<void()> save, restore;
  };
  std::vector<KeptValue> keptValues_;
  double nextSnapshotTime_ = 0.0;

  // Mouse drag: the object's index, the grabbed point in its body's frame.
  int dragIndex_ = -1;
  double dragGrab_[3] = {0, 0, 0};
  double dragTarget_[3] = {0, 0, 0};

  ViewFlags viewFlags_;
  std::vector<ContactMarker> contactMarkers_;
  StripChart chart_;
  double nextChartTime_ = 0.0;
  bool screenshotRequested_ = false;
  Metrics marks_;
  std::FILE* runLog_ = nullptr;
  std::string lastChange_;  // what applySettings() reported during the last key
  bool runLogFailed_ = false;
};

}  // namespace odelab
