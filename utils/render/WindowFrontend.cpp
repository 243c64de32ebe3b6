#include "WindowFrontend.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "../CompareLanes.h"
#include "../ExitCodes.h"
#include "../MeasurementLog.h"
#include "../StopSignal.h"
#include "../StreamedFile.h"
#include "../ResourcePaths.h"
#include "CompareViews.h"
#include "ControlPanel.h"
#include "DebugDraw.h"
#include "EventPlayer.h"
#include "FrameProfile.h"
#include "GhostDraw.h"
#include "GlWindow.h"
#include "HelpOverlay.h"
#include "HudText.h"
#include "LivePlot.h"
#include "Renderer.h"
#include "Screenshot.h"
#include "WindowInput.h"
#ifdef __EMSCRIPTEN__
#include "../web/WebMainLoop.h"
#endif

namespace odelab {

namespace {

// A paused window with nothing to show redraws only when an event comes,
// or after this long (the notices time out).
const int IDLE_WAIT_MS = 1000;
// With --record every frame stands for 1/60 s of simulated time (times the
// time scale), however long writing it takes, so the frames make a 60 fps
// video that plays in real time.
const double RECORD_FRAME_SECONDS = 1.0 / 60.0;
const double NOTICE_SECONDS = 4.0;
const int MARGIN = 10;

// Totals of the run, printed at exit and at each scripted mark (the
// benchmark reads them): frames, real seconds, and the part of them spent
// drawing and stepping rather than waiting for the next frame.
struct FrameTotals {
  long long frames = 0;
  double seconds = 0.0;
  double busySeconds = 0.0;
  double longestFrame = 0.0;  // seconds, from one frame's start to the next's
  double drawSeconds = 0.0;   // drawing and the swap
  double loopSeconds = 0.0;   // from the first frame's start to the last one's end
};

// Also the process's CPU time so far (all threads: Mesa's software renderer
// draws on several), which a busy machine disturbs less than the frame rate.
void printTotals(const char* what, const FrameTotals& t) {
  std::printf(
      "%s: %lld frames in %.3f s (%.1f fps; %.3f ms per frame drawing and stepping; longest frame %.1f ms; CPU %.3f s)\n",
      what, t.frames, t.seconds, t.seconds > 0 ? static_cast<double>(t.frames) / t.seconds : 0.0,
      t.frames > 0 ? 1000.0 * t.busySeconds / static_cast<double>(t.frames) : 0.0, 1000.0 * t.longestFrame,
      static_cast<double>(std::clock()) / CLOCKS_PER_SEC);
  std::fflush(stdout);
}

// A compare window's totals (the compare benchmark reads them): each
// engine's stepping (its steps, its measurement and, for another engine,
// the transfers), and the drawing.
void printCompareTotals(const CompareLanes* lanes, const FrameTotals& t) {
  if (!lanes) return;
  std::printf("compare: %lld frames in %.3f s; stepping s:", t.frames, t.loopSeconds);
  for (const CompareLanes::Lane& lane : lanes->lanes()) std::printf(" %s %.3f", lane.engine.c_str(), lane.steppingSeconds);
  std::printf("; drawing s: %.3f (the swap included)\n", t.drawSeconds);
  std::fflush(stdout);
}

bool finished(const AbstractWindow& scene, const RunOptions& options) {
  return scene.session().quitRequested() || stopSignal() != 0 || (options.seconds > 0.0 && scene.run().simulatedTime() >= options.seconds);
}

// Everything drawn in a window, built once the GL context exists and
// destroyed before it goes.
struct Views {
  Views(const std::string& shaderDir, const std::string& fontPath, GlWindow& window, const RunOptions& options)
      : renderer(shaderDir),
        text(fontPath, shaderDir),
        debug(shaderDir),
        plot(shaderDir),
        compare(shaderDir),
        ghost(shaderDir),
        panel(window.sdlWindow(), window.glContext(), fontPath,
              textPixelsFor(options.textSize, window.height()),
              options.panel) {}
  Renderer renderer;
  HudText text;
  DebugDraw debug;
  LivePlot plot;
  CompareViews compare;
  GhostDraw ghost;
  ControlPanel panel;
  HelpOverlay help;
  TextBlock notice{200};
};

std::string formatFixed(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

class FrameLoop {
 public:
  // `windowFrames` counts the window's frames over every scene it shows.
  // `lanes`: a compare window's other engines, which follow the scene.
  FrameLoop(AbstractWindow& scene, const RunOptions& options, GlWindow& window, Views& views, EventPlayer& player,
            long long& windowFrames, CompareLanes* lanes = nullptr)
      : scene_(scene),
        options_(options),
        window_(window),
        views_(views),
        player_(player),
        windowFrames_(windowFrames),
        lanes_(lanes) {
    if (lanes_) views_.panel.showEngines(views_.compare, *lanes_);
  }

  int run();
  double runFrame();
  bool over() const;
  void end();  // prints the totals once (a screenshot at the end prints them already)

 private:
  void pollEvents(long long frame);
  void draw();
  void drawCompare(int width, int height, int sceneHeight);
  bool handleCompareKey(const SDL_Event& event);
  ViewRect compareInputView(const SDL_Event& event, const ViewRect& whole, int windowWidth);
  void drawHelp(int width, int height);
  bool turnHelpPage(const SDL_Event& event);
  void drawNotice(int width, int height);
  void saveRequestedScreenshot();
  void recordFrame(long long frame);

  AbstractWindow& scene_;
  const RunOptions& options_;
  GlWindow& window_;
  Views& views_;
  EventPlayer& player_;
  // --record numbers frames by this count, so a scene shown again after a
  // switch goes on from the window's last frame instead of replacing the
  // frames of its first visit.
  long long& windowFrames_;
  CompareLanes* lanes_;
  // The compare views of the last frame (pixels from the top left), and the
  // one a held mouse button began in: a drag stays in its view.
  std::vector<CompareViews::Rect> compareViews_;
  int heldView_ = -1;
  Uint64 firstFrameStart_ = 0;
  bool idle() const;
  double seconds(Uint64 from, Uint64 to) const { return static_cast<double>(to - from) / ticksPerSecond_; }

  WindowInput input_{scene_};  // after scene_: it takes the tuning the scene starts with
  FrameTotals totals_;
  bool totalsPrinted_ = false;
  double ticksPerSecond_ = static_cast<double>(SDL_GetPerformanceFrequency());
  std::string notice_;
  double noticeUntil_ = 0.0;
  long long frame_ = 0;
  Uint64 previous_ = SDL_GetPerformanceCounter();
  // The frame cap, unless vsync already waits for the display.
  double period_ = options_.maxFps > 0 && !window_.vsync() ? 1.0 / options_.maxFps : 0.0;
  int hudStrip_ = 0;  // pixels at the top the HUD took in the last frame
  FrameProfile profile_;
};

void FrameLoop::pollEvents(long long frame) {
  player_.pushDue(frame);
  int windowWidth = 0, windowHeight = 0;
  window_.windowSize(windowWidth, windowHeight);
  SDL_Event event;
  while (SDL_PollEvent(&event)) {
    if (player_.handle(event, scene_, [this](const std::string& label) { printTotals(("mark " + label).c_str(), totals_); }))
      continue;
    if (views_.panel.handleEvent(event)) continue;
    if (turnHelpPage(event)) continue;
    if (handleCompareKey(event)) continue;
    if (event.type == SDL_KEYDOWN && event.key.keysym.sym == SDLK_TAB && !event.key.repeat) {
      views_.panel.toggle();
      continue;
    }
    // The scene's view is the window less the panel's column and the HUD's
    // strip (in window coordinates, which differ from pixels on a high-DPI display).
    const int covered = window_.width() > 0 ? views_.panel.coveredWidth() * windowWidth / window_.width() : 0;
    const int strip = window_.height() > 0 ? hudStrip_ * windowHeight / window_.height() : 0;
    ViewRect view{0, strip, windowWidth - covered, windowHeight - strip};
    if (lanes_) view = compareInputView(event, view, windowWidth);
    if (input_.handleEvent(event, scene_, view))
      window_.updateDrawableSize();
  }
  syncMouseLook(scene_);
}

// Page Down / Space and Page Up turn the help's pages while it is open.
bool FrameLoop::turnHelpPage(const SDL_Event& event) {
  if (!scene_.session().viewFlags().help) {
    views_.help.close();
    return false;
  }
  if (event.type != SDL_KEYDOWN) return false;
  const SDL_Keycode key = event.key.keysym.sym;
  if (key == SDLK_PAGEDOWN || key == SDLK_SPACE) views_.help.turn(+1);
  else if (key == SDLK_PAGEUP) views_.help.turn(-1);
  else return false;
  return true;
}

// The compare window's own keys: M merges the views; a scene switch (the
// launcher's Page Down / Up) would end every engine's run, so it is refused.
bool FrameLoop::handleCompareKey(const SDL_Event& event) {
  if (!lanes_ || event.type != SDL_KEYDOWN || event.key.repeat) return false;
  const SDL_Keycode key = event.key.keysym.sym;
  if (key == SDLK_m) {
    views_.compare.toggleMerged();
    return true;
  }
  if (key == SDLK_PAGEDOWN || key == SDLK_PAGEUP) {
    notice_ = "a compare window shows one scene: start another to compare it";
    noticeUntil_ = totals_.seconds + NOTICE_SECONDS;
    return true;
  }
  return false;
}

// The mouse works in the view it is over, each with the same camera, so a
// click picks what it is over there (on ODE's bodies, which every engine's
// scene mirrors by index); a drag stays in the view it began in.
ViewRect FrameLoop::compareInputView(const SDL_Event& event, const ViewRect& whole, int windowWidth) {
  if (compareViews_.empty() || window_.width() <= 0) return whole;
  const double toWindow = static_cast<double>(windowWidth) / window_.width();
  const auto inWindow = [&](const CompareViews::Rect& r) {
    return ViewRect{static_cast<int>(r.x * toWindow), static_cast<int>(r.y * toWindow),
                    static_cast<int>(r.width * toWindow), static_cast<int>(r.height * toWindow)};
  };
  int x = -1, y = -1;
  if (event.type == SDL_MOUSEBUTTONDOWN || event.type == SDL_MOUSEBUTTONUP) x = event.button.x, y = event.button.y;
  else if (event.type == SDL_MOUSEMOTION) x = event.motion.x, y = event.motion.y;
  int chosen = heldView_;
  if (chosen < 0 && x >= 0) {
    for (size_t i = 0; i < compareViews_.size(); ++i) {
      const ViewRect r = inWindow(compareViews_[i]);
      if (x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height) chosen = static_cast<int>(i);
    }
  }
  if (event.type == SDL_MOUSEBUTTONDOWN && chosen >= 0) heldView_ = chosen;
  if (event.type == SDL_MOUSEBUTTONUP && !(SDL_GetMouseState(nullptr, nullptr) & ~SDL_BUTTON(event.button.button)))
    heldView_ = -1;
  return inWindow(compareViews_[static_cast<size_t>(std::max(chosen, 0))]);
}

void FrameLoop::drawHelp(int width, int height) {
  std::vector<std::string> lines{scene_.title() + ": keys and mouse   (H closes this)", ""};
  if (lanes_) lines.push_back(CompareViews::helpLine());
  for (const std::string& line : scene_.helpLines()) lines.push_back(line);
  views_.help.draw(views_.text, lines, width, height);
}

void FrameLoop::drawNotice(int width, int height) {
  if (notice_.empty() || totals_.seconds > noticeUntil_) return;
  views_.text.prepare(views_.notice, {notice_}, width - 2 * MARGIN);
  views_.text.drawAt(views_.notice, MARGIN, height - MARGIN - views_.notice.height(), width, height);
}

void FrameLoop::draw() {
  // The panel is a column at the right edge and the HUD a strip across the
  // top; the scene takes the rest, so neither covers the subject. The plot
  // and the notice sit in the view's bottom corners.
  const int windowWidth = window_.width(), height = window_.height();
  const int width = std::max(1, windowWidth - views_.panel.coveredWidth());
  views_.text.setSizeFor(options_.textSize, height);
  std::vector<std::string> hud = scene_.hudLines();
  // The lines that come and go take one row each: the notices and messages
  // at the end and, in the full HUD, where the frame's time goes (its row
  // kept blank until the first second is measured).
  std::vector<bool> oneRow(hud.size(), false);
  std::fill(oneRow.end() - static_cast<long>(std::min(oneRow.size(), scene_.hudPassingLines().size())), oneRow.end(), true);
  if (scene_.session().hudMode() == HudMode::Full) {
    const long at = std::min<long>(3, static_cast<long>(hud.size()));
    hud.insert(hud.begin() + at, profile_.text());
    oneRow.insert(oneRow.begin() + at, true);
  }
  // A compare window says how it is laid out and what each engine's step costs.
  if (lanes_ && scene_.session().hudMode() != HudMode::Off) {
    insertCompareLines(hud, oneRow, lanes_->timingLine(), views_.compare.hudLine());
  }
  // A world file's ghost says what it draws (every view draws it, so the one HUD line serves them all).
  if (scene_.ghost() && scene_.session().hudMode() != HudMode::Off)
    insertGhostLine(hud, oneRow, GhostDraw::hudLine(*scene_.ghost()));
  hudStrip_ = views_.text.layoutHud(hud, width, height * HUD_MAX_PERCENT / 100, scene_.session().hudMode() == HudMode::Full,
                                    oneRow);
  const int sceneHeight = std::max(1, height - hudStrip_);
  if (lanes_) {
    drawCompare(width, height, sceneHeight);
  } else {
    scene_.camera().setAspect(static_cast<float>(width) / static_cast<float>(sceneHeight));
    views_.renderer.render(scene_, width, sceneHeight);
    glm::vec3 grabbed, target;
    const bool dragging = input_.dragLine(scene_, grabbed, target);
    views_.compare.drawEdges(scene_, scene_.engine().active() ? scene_.engine().engineName() : "ode",
                             views_.renderer.viewProjection());
    views_.ghost.draw(scene_, views_.renderer.viewProjection());
    views_.debug.draw(scene_, views_.renderer.viewProjection(), dragging, grabbed, target);
    views_.renderer.present();
  }
  glViewport(0, 0, width, height);
  views_.text.drawHud(width, height);
  const ViewFlags& flags = scene_.session().viewFlags();
  if (flags.plot && lanes_)
    views_.plot.draw(scene_.session().chart(), views_.text, width, height, views_.compare.curves(*lanes_),
                     views_.compare.legend(*lanes_));
  else if (flags.plot)
    views_.plot.draw(scene_.session().chart(), views_.text, width, height);
  drawNotice(width, height);
  views_.panel.draw(scene_, windowWidth, height);
  // The help is read, not worked beside: it takes the whole window, over
  // the panel too, for room to stay in columns rather than run off.
  if (flags.help) {
    glViewport(0, 0, windowWidth, height);
    drawHelp(windowWidth, height);
  }
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

// Every engine's view with the one camera, and the debug drawing each
// engine's scene reports (contacts, joints) with ODE's view toggles; merged,
// ODE's view with the others' outlines. Then each view's label.
void FrameLoop::drawCompare(int width, int height, int sceneHeight) {
  compareViews_ = views_.compare.layout(*lanes_, hudStrip_, width, sceneHeight);
  const CompareViews::Rect& first = compareViews_.front();
  scene_.camera().setAspect(static_cast<float>(first.width) / static_cast<float>(first.height));
  views_.renderer.clearWindow();
  glm::vec3 grabbed, target;
  const bool dragging = input_.dragLine(scene_, grabbed, target);
  for (const CompareViews::Rect& r : compareViews_) {
    AbstractWindow& lane = *lanes_->lanes()[r.lane].scene;
    if (&lane != &scene_) {
      lane.camera() = scene_.camera();
      lane.session().showAs(scene_.session().viewFlags());
    }
    views_.renderer.renderView(lane, scene_.camera(), r.x, height - r.y - r.height, r.width, r.height);
    views_.compare.drawEdges(lane, lanes_->lanes()[r.lane].engine, views_.renderer.viewProjection());
    views_.ghost.draw(lane, views_.renderer.viewProjection());
    views_.debug.draw(lane, views_.renderer.viewProjection(), dragging && r.lane == 0, grabbed, target);
    if (views_.compare.merged()) views_.compare.drawOutlines(*lanes_, views_.renderer.viewProjection());
    views_.renderer.present();
  }
  glViewport(0, 0, width, height);
  views_.compare.drawLabels(*lanes_, compareViews_, views_.text, width, height);
}

// F12: the frame as shown, named with the program and the simulated time.
// A failure is reported and the session goes on.
void FrameLoop::saveRequestedScreenshot() {
  // A second F12 at the same simulated time (paused) gets _2, _3, ...
  const std::string stem =
      joinPath(options_.outDir, scene_.programName() + "_t" + formatFixed("%.3f", scene_.run().simulatedTime()));
  std::string path = stem + ".png";
  std::error_code error;
  for (int n = 2; std::filesystem::exists(path, error); ++n) path = stem + "_" + std::to_string(n) + ".png";
  try {
    saveScreenshot(path, window_.width(), window_.height());
    std::printf("screenshot: %s\n", path.c_str());
    std::fflush(stdout);
    notice_ = "saved " + path;
  } catch (const RenderError& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    notice_ = error.what();
  }
  noticeUntil_ = totals_.seconds + NOTICE_SECONDS;
}

void FrameLoop::recordFrame(long long frame) {
  char name[48];
  std::snprintf(name, sizeof name, "_frame_%06lld.png", frame);
  saveScreenshot(joinPath(options_.recordDir, scene_.programName() + name), window_.width(), window_.height());
}

void sayWhereFilesGo(const AbstractWindow& scene, const RunOptions& options) {
  const std::vector<std::string> names = scene.outputFileNames();
  if (names.empty()) return;
  std::string list;
  for (size_t i = 0; i < names.size(); ++i)
    list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  std::error_code failed;
  std::filesystem::path folder =
      std::filesystem::absolute(options.outDir.empty() ? "." : options.outDir, failed).lexically_normal();
  if (folder.has_parent_path() && folder.filename().empty()) folder = folder.parent_path();  // "/a/b/" -> "/a/b"
  std::fprintf(stderr, "%s writes %s in %s (--out-dir DIR chooses the folder)\n", scene.programName().c_str(),
               list.c_str(), failed ? options.outDir.c_str() : folder.string().c_str());
}

// Paused, with no rewind under way, no script playing, no key flying the camera and no drag:
// nothing changes until an event comes.
bool FrameLoop::idle() const {
  return scene_.session().time().paused() && !scene_.rewinding() && !player_.playing() && !cameraKeysHeld() &&
         !scene_.session().dragging() &&
         options_.recordDir.empty() && options_.screenshot.empty();
}

// One pass of the loop: events, steps, drawing and the swap. Returns the
// seconds it was busy, or a negative number when it was a screenshot run's
// last frame. The desktop loop below and the browser's per-frame callback
// both call it, so a frame is the same on both.
double FrameLoop::runFrame() {
  const bool screenshotRun = !options_.screenshot.empty();
  const bool recording = !options_.recordDir.empty();
  const int screenshotFrame = options_.frames > 0 ? options_.frames : 1;
  const long long frame = ++frame_;
  ++windowFrames_;
  const Uint64 start = SDL_GetPerformanceCounter();
  pollEvents(frame);

  const Uint64 now = SDL_GetPerformanceCounter();
  const double elapsed = seconds(previous_, now);
  previous_ = now;
  moveCamera(scene_, elapsed);
  const double simulatedBefore = scene_.run().simulatedTime();
  const long long stepsBefore = scene_.run().steps();
  const double collideBefore = scene_.run().collideWallSeconds();
  // An OdeError leaves through here; RAII cleans up. A compare window
  // shares the stepping budget among its engines.
  const double engines = lanes_ ? static_cast<double>(lanes_->lanes().size()) : 1.0;
  const bool rewindFrame = scene_.rewinding();  // begun by this frame's keys, or before
  // A rewind replays, each frame, what every engine can replay in the budget.
  if (lanes_) scene_.setRewindStepsPerFrame(lanes_->stepsWithin(TimeControl::STEPPING_BUDGET));
  scene_.advanceFrame(recording ? RECORD_FRAME_SECONDS : elapsed,
                      recording ? std::numeric_limits<double>::infinity() : TimeControl::STEPPING_BUDGET / engines);
  if (lanes_) lanes_->follow(seconds(now, SDL_GetPerformanceCounter()), scene_.run().steps() - stepsBefore);
  const double stepping = seconds(now, SDL_GetPerformanceCounter());
  if (rewindFrame) scene_.noteRewindFrame(stepping);
  input_.followBody(scene_);
  // A reset or a rewind moves time back: only forward steps count.
  const double advanced =
      scene_.run().steps() > stepsBefore ? std::max(0.0, scene_.run().simulatedTime() - simulatedBefore) : 0.0;

  const Uint64 drawStart = SDL_GetPerformanceCounter();
  draw();
  const Uint64 drawEnd = SDL_GetPerformanceCounter();
  // Read the back buffer before the swap leaves its contents undefined.
  const bool screenshotNow = screenshotRun && (options_.screenshotAtEnd ? over() : frame == screenshotFrame);
  if (scene_.session().takeScreenshotRequest()) saveRequestedScreenshot();
  if (recording) recordFrame(windowFrames_);
  if (screenshotNow) saveScreenshot(options_.screenshot, window_.width(), window_.height());

  ++totals_.frames;
  totals_.seconds += elapsed;
  totals_.longestFrame = std::max(totals_.longestFrame, elapsed);
  if (!screenshotNow) window_.swap();  // a software renderer does much of its work here
  const Uint64 swapped = SDL_GetPerformanceCounter();
  const double busy = seconds(start, swapped);
  profile_.add(scene_.run().collideWallSeconds() - collideBefore, stepping, seconds(drawStart, drawEnd),
               seconds(drawEnd, swapped), elapsed);
  totals_.busySeconds += busy;
  totals_.drawSeconds += seconds(drawStart, swapped);
  if (frame == 1) firstFrameStart_ = start;
  totals_.loopSeconds = seconds(firstFrameStart_, swapped);
  scene_.session().time().endFrame(elapsed, advanced, stepping, busy, period_);
  if (screenshotNow) {
    std::printf("screenshot: %s (%dx%d, frame %lld)\n", options_.screenshot.c_str(), window_.width(),
                window_.height(), frame);
    // Where each engine is in the picture, for a reader (or a check) to crop.
    for (size_t i = 0; lanes_ && i < compareViews_.size(); ++i) {
      const CompareViews::Rect& r = compareViews_[i];
      std::printf("view %s: x %d y %d width %d height %d (pixels from the top left)\n",
                  views_.compare.merged() ? "merged" : lanes_->lanes()[r.lane].engine.c_str(), r.x, r.y, r.width,
                  r.height);
    }
    end();
    return -1.0;
  }
  return busy;
}

bool FrameLoop::over() const { return finished(scene_, options_); }

void FrameLoop::end() {
  if (totalsPrinted_) return;
  totalsPrinted_ = true;
  printTotals("window", totals_);
  printCompareTotals(lanes_, totals_);
}

int FrameLoop::run() {
  while (!over()) {
    if (idle()) SDL_WaitEventTimeout(nullptr, IDLE_WAIT_MS);
    const double busy = runFrame();
    if (busy < 0.0) return exit_code::OK;
    if (busy < period_) SDL_Delay(static_cast<Uint32>((period_ - busy) * 1000.0));
  }
  end();
  return exit_code::OK;
}

std::vector<ScriptEvent> loadScript(const RunOptions& options) {
  if (options.eventsFile.empty()) return {};
  // Key names need no video subsystem: SDL_GetKeyFromName uses SDL's default keymap.
  return loadEventScript(options.eventsFile,
                         [](const std::string& name) { return static_cast<int>(SDL_GetKeyFromName(name.c_str())); });
}

}  // namespace

void checkWindowOptions(const RunOptions& options) { loadScript(options); }

int runWindow(AbstractWindow& scene, const RunOptions& options, const std::function<int(int)>& finish) {
  return runWindowSwitching(scene, options, nullptr, finish);
}

namespace {

int runWindowWith(AbstractWindow& first, const RunOptions& options,
                  const std::function<AbstractWindow&(int direction)>& next, const std::function<int(int)>& finish,
                  CompareLanes* lanes);

}  // namespace

int runWindowSwitching(AbstractWindow& first, const RunOptions& options,
                       const std::function<AbstractWindow&(int direction)>& next,
                       const std::function<int(int)>& finish) {
  return runWindowWith(first, options, next, finish, nullptr);
}

int runCompareWindow(CompareLanes& lanes, const RunOptions& options, const std::function<int(int)>& finish) {
  return runWindowWith(*lanes.lanes().front().scene, options, nullptr, finish, &lanes);
}

namespace {

// Built only once the window can run, so that a refused window run (no
// display, unusable shaders or font) leaves no output file behind; a runner
// that built them already is fine too. Each other engine's scene with its
// own options (its engine, its folder). Every scene is built under one hold
// on the streamed outputs, released only once the last engine has built its
// scene: an engine that refuses (its process dies, it cannot build the
// scene) leaves every engine's files as the previous run left them, as in
// the headless compare run (CompareRun::run). Each scene's own hold nests
// in this one.
void initializeScenes(AbstractWindow& scene, const RunOptions& options, const CompareLanes* lanes) {
  StreamedFile::Hold outputsHeld;
  if (!scene.run().world()) scene.initialize(options);
  if (lanes)
    for (const CompareLanes::Lane& lane : lanes->lanes())
      if (!lane.scene->run().world()) lane.scene->initialize(lane.scene->options());
  outputsHeld.release();
}

int runWindowWith(AbstractWindow& first, const RunOptions& options,
                  const std::function<AbstractWindow&(int direction)>& next, const std::function<int(int)>& finish,
                  CompareLanes* lanes) {
  const ResourceLookup shaders = findShaderDir(options.shaderDir);
  if (!shaders.ok()) {
    std::fprintf(stderr, "error: shaders not found; tried: %s\n", shaders.triedList().c_str());
    return finish(exit_code::MISSING_RESOURCE);
  }
  const ResourceLookup font = findFont(options.fontPath);
  if (!font.ok()) {
    std::fprintf(stderr, "error: font not found; tried: %s\n", font.triedList().c_str());
    return finish(exit_code::MISSING_RESOURCE);
  }
  // A script with a mistake stops the run before a window opens (UsageError,
  // exit status 2).
  std::vector<ScriptEvent> script = loadScript(options);

  AbstractWindow* scene = &first;  // the scene on screen
  try {
    // Made in this order so GL objects go before the context they live in.
    auto window = std::make_unique<GlWindow>(first.title(), options.width, options.height, options.vsync);
    auto views = std::make_unique<Views>(shaders.found, font.found, *window, options);
    views->renderer.setSoftware(window->software());
    std::printf("renderer: %s%s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                window->software() ? " (software: no multisampling, shadows filtered over one texel)" : "");
    // One script for the whole window; after a switch its frame numbers
    // count the new scene's frames from 1.
    auto player = std::make_unique<EventPlayer>(std::move(script), window->sdlWindow());
#ifdef __EMSCRIPTEN__
    (void)next;
    initializeScenes(*scene, options, lanes);
    // The frames outlive this call and the caller's options: they keep a
    // copy for the page's life. A page runs one scene (no switching).
    const RunOptions& frameOptions = *new RunOptions(options);
    auto loop = std::make_unique<FrameLoop>(*scene, frameOptions, *window, *views, *player, *new long long(0), lanes);
    // The browser calls the frame back; this function never returns, and
    // what the frames use lives as long as the page.
    FrameLoop* frames = loop.get();
    window.release(), views.release(), player.release(), loop.release();
    web::runEveryFrame([frames] { return !frames->over() && frames->runFrame() >= 0.0; },
                       [frames, finish] {
                         frames->end();
                         return finish(exit_code::OK);
                       });
    return exit_code::OK;
#else
    (void)next;
    long long windowFrames = 0;
    for (;;) {
      initializeScenes(*scene, options, lanes);
      // The launcher's window visits scenes that write files: each visit
      // says which and where, since no option of the user's named them.
      if (next) sayWhereFilesGo(*scene, options);
      FrameLoop loop(*scene, options, *window, *views, *player, windowFrames, lanes);
      const int status = loop.run();
      if (!next || !scene->session().switchRequested() || stopSignal() != 0) return finish(status);
      // `next` destroys the scene that ended before it makes the next one.
      const int offset = scene->session().switchRequest();
      scene = nullptr;
      scene = &next(offset);
      SDL_SetWindowTitle(window->sdlWindow(), scene->title().c_str());
    }
#endif
  } catch (const NoDisplayError& error) {
    std::fprintf(stderr, "error: cannot open a window (%s); set DISPLAY or run with --headless\n", error.what());
    return finish(exit_code::NO_DISPLAY);
  } catch (const ResourceError& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return finish(exit_code::MISSING_RESOURCE);
  } catch (const RenderError& error) {
    // A frame that cannot be recorded (a full disk), a GL failure: the
    // output files name it as the reason the run was cut short.
    std::fprintf(stderr, "error: %s\n", error.what());
    if (scene) scene->endOutputs(error.what());
    return finish(exit_code::RUNTIME_ERROR);
  }
}

}  // namespace

}  // namespace odelab
