#pragma once

#include <SDL2/SDL_keycode.h>
#include <ode/ode.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "AbstractObject.h"
#include "Camera.h"
#include "FixedStepClock.h"
#include "Metrics.h"
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
};

// One key of the scene: the same table drives dispatch, --help and doc/.
struct KeyBinding {
  SDL_Keycode key;
  std::string keyName;
  std::string description;
  std::function<void(int direction)> action;  // direction is -1 with Shift, else +1
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
  // Destroys the world, space and every object; call before dCloseODE().
  void shutdown();
  // Window path: feeds one frame's elapsed real time through the clock and
  // runs the resulting steps. A blow-up is reported and the scene reset.
  void advanceFrame(double elapsedSeconds);
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

  // Scene keys. B / N / F5 are bound through these when the scene supports them.
  void bindKey(SDL_Keycode key, std::string keyName, std::string description,
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
  void bindSharedKeys();
  void stepSetting(const char* what, const std::function<void()>& change);
  bool stateIsFinite() const;

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
  double rateWindowReal_ = 0.0, rateWindowSim_ = 0.0;
  std::string notice_;
  double noticeUntil_ = 0.0;  // in real seconds of window time
};

}  // namespace odelab
