#include "WindowFrontend.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

#include "../ExitCodes.h"
#include "../MeasurementLog.h"
#include "../StopSignal.h"
#include "../ResourcePaths.h"
#include "ControlPanel.h"
#include "DebugDraw.h"
#include "EventPlayer.h"
#include "GlWindow.h"
#include "HudText.h"
#include "LivePlot.h"
#include "Renderer.h"
#include "Screenshot.h"
#include "WindowInput.h"

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

bool finished(const AbstractWindow& scene, const RunOptions& options) {
  return scene.quitRequested() || stopSignal() != 0 || (options.seconds > 0.0 && scene.simulatedTime() >= options.seconds);
}

// Everything drawn in a window, built once the GL context exists and
// destroyed before it goes.
struct Views {
  Views(const std::string& shaderDir, const std::string& fontPath, GlWindow& window, const RunOptions& options)
      : renderer(shaderDir),
        text(fontPath, shaderDir),
        debug(shaderDir),
        plot(shaderDir),
        panel(window.sdlWindow(), window.glContext(), fontPath,
              options.textSize > 0 ? options.textSize : std::min(28, std::max(12, window.height() / 45)),
              options.panel) {}
  Renderer renderer;
  HudText text;
  DebugDraw debug;
  LivePlot plot;
  ControlPanel panel;
  TextBlock help{240};
  TextBlock notice{200};
};

std::string formatFixed(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

class FrameLoop {
 public:
  FrameLoop(AbstractWindow& scene, const RunOptions& options, GlWindow& window, Views& views, EventPlayer& player)
      : scene_(scene), options_(options), window_(window), views_(views), player_(player) {}

  int run();

 private:
  void pollEvents(long long frame);
  void draw();
  void drawHelp(int width, int height);
  void drawNotice(int width, int height);
  void saveRequestedScreenshot();
  void recordFrame(long long frame);

  AbstractWindow& scene_;
  const RunOptions& options_;
  GlWindow& window_;
  Views& views_;
  EventPlayer& player_;
  bool idle() const;
  double seconds(Uint64 from, Uint64 to) const { return static_cast<double>(to - from) / ticksPerSecond_; }

  WindowInput input_;
  FrameTotals totals_;
  double ticksPerSecond_ = static_cast<double>(SDL_GetPerformanceFrequency());
  std::string notice_;
  double noticeUntil_ = 0.0;
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
    if (event.type == SDL_KEYDOWN && event.key.keysym.sym == SDLK_TAB && !event.key.repeat) {
      views_.panel.toggle();
      continue;
    }
    // The scene's view is the window less the panel's column (in window
    // coordinates, which differ from pixels on a high-DPI display).
    const int covered = window_.width() > 0 ? views_.panel.coveredWidth() * windowWidth / window_.width() : 0;
    if (input_.handleEvent(event, scene_, windowWidth - covered, windowHeight)) window_.updateDrawableSize();
  }
  syncMouseLook(scene_);
}

void FrameLoop::drawHelp(int width, int height) {
  std::vector<std::string> lines{scene_.title() + ": keys and mouse   (H closes this)", ""};
  for (const std::string& line : scene_.helpLines()) lines.push_back(line);
  views_.text.prepare(views_.help, lines, width - 2 * MARGIN);
  const int x = std::max(MARGIN, (width - views_.help.width()) / 2);
  const int y = std::max(MARGIN, (height - views_.help.height()) / 2);
  views_.text.drawAt(views_.help, x, y, width, height);
}

void FrameLoop::drawNotice(int width, int height) {
  if (notice_.empty() || totals_.seconds > noticeUntil_) return;
  views_.text.prepare(views_.notice, {notice_}, width - 2 * MARGIN);
  views_.text.drawAt(views_.notice, MARGIN, height - MARGIN - views_.notice.height(), width, height);
}

void FrameLoop::draw() {
  // The panel is a column at the right edge; the scene, the HUD and the
  // overlays share the rest, so the panel never covers the subject.
  const int windowWidth = window_.width(), height = window_.height();
  const int width = std::max(1, windowWidth - views_.panel.coveredWidth());
  views_.renderer.render(scene_, width, height);
  glm::vec3 grabbed, target;
  const bool dragging = input_.dragLine(scene_, grabbed, target);
  views_.debug.draw(scene_, views_.renderer.viewProjection(), dragging, grabbed, target);
  views_.text.setSizeFor(options_.textSize, height);
  views_.text.draw(scene_.hudLines(), width, height);
  const ViewFlags& flags = scene_.viewFlags();
  if (flags.plot) views_.plot.draw(scene_.chart(), views_.text, width, height);
  if (flags.help) drawHelp(width, height);
  drawNotice(width, height);
  views_.panel.draw(scene_, windowWidth, height);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

// F12: the frame as shown, named with the program and the simulated time.
// A failure is reported and the session goes on.
void FrameLoop::saveRequestedScreenshot() {
  // A second F12 at the same simulated time (paused) gets _2, _3, ...
  const std::string stem =
      joinPath(options_.outDir, scene_.programName() + "_t" + formatFixed("%.3f", scene_.simulatedTime()));
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
  char name[32];
  std::snprintf(name, sizeof name, "_frame_%06lld.png", frame);
  saveScreenshot(joinPath(options_.recordDir, scene_.programName() + name), window_.width(), window_.height());
}

// Paused, with no script playing, no key flying the camera and no drag:
// nothing changes until an event comes.
bool FrameLoop::idle() const {
  return scene_.time().paused() && !player_.playing() && !cameraKeysHeld() && !scene_.dragging() &&
         options_.recordDir.empty() && options_.screenshot.empty();
}

int FrameLoop::run() {
  const bool screenshotRun = !options_.screenshot.empty();
  const bool recording = !options_.recordDir.empty();
  const int screenshotFrame = options_.frames > 0 ? options_.frames : 1;
  // The frame cap, unless vsync already waits for the display.
  const double period = options_.maxFps > 0 && !window_.vsync() ? 1.0 / options_.maxFps : 0.0;
  Uint64 previous = SDL_GetPerformanceCounter();

  for (long long frame = 1; !finished(scene_, options_); ++frame) {
    if (idle()) SDL_WaitEventTimeout(nullptr, IDLE_WAIT_MS);
    const Uint64 start = SDL_GetPerformanceCounter();
    pollEvents(frame);

    const Uint64 now = SDL_GetPerformanceCounter();
    const double elapsed = seconds(previous, now);
    previous = now;
    moveCamera(scene_, elapsed);
    const double simulatedBefore = scene_.simulatedTime();
    const long long stepsBefore = scene_.steps();
    // An OdeError leaves through here; RAII cleans up.
    scene_.advanceFrame(recording ? RECORD_FRAME_SECONDS : elapsed,
                        recording ? std::numeric_limits<double>::infinity() : TimeControl::STEPPING_BUDGET);
    const double stepping = seconds(now, SDL_GetPerformanceCounter());
    // A reset or a rewind moves time back: only forward steps count.
    const double advanced =
        scene_.steps() > stepsBefore ? std::max(0.0, scene_.simulatedTime() - simulatedBefore) : 0.0;

    draw();
    // Read the back buffer before the swap leaves its contents undefined.
    const bool screenshotNow = screenshotRun && frame == screenshotFrame;
    if (scene_.takeScreenshotRequest()) saveRequestedScreenshot();
    if (recording) recordFrame(frame);
    if (screenshotNow) saveScreenshot(options_.screenshot, window_.width(), window_.height());

    ++totals_.frames;
    totals_.seconds += elapsed;
    totals_.longestFrame = std::max(totals_.longestFrame, elapsed);
    if (!screenshotNow) window_.swap();  // a software renderer does much of its work here
    const double busy = seconds(start, SDL_GetPerformanceCounter());
    totals_.busySeconds += busy;
    scene_.time().endFrame(elapsed, advanced, stepping, busy, period);
    if (screenshotNow) {
      std::printf("screenshot: %s (%dx%d, frame %lld)\n", options_.screenshot.c_str(), window_.width(),
                  window_.height(), frame);
      printTotals("window", totals_);
      return exit_code::OK;
    }
    if (busy < period) SDL_Delay(static_cast<Uint32>((period - busy) * 1000.0));
  }
  printTotals("window", totals_);
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

int runWindow(AbstractWindow& scene, const RunOptions& options) {
  return runWindowSwitching(scene, options, nullptr);
}

int runWindowSwitching(AbstractWindow& first, const RunOptions& options,
                       const std::function<AbstractWindow&(int direction)>& next) {
  const ResourceLookup shaders = findShaderDir(options.shaderDir);
  if (!shaders.ok()) {
    std::fprintf(stderr, "error: shaders not found; tried: %s\n", shaders.triedList().c_str());
    return exit_code::MISSING_RESOURCE;
  }
  const ResourceLookup font = findFont(options.fontPath);
  if (!font.ok()) {
    std::fprintf(stderr, "error: font not found; tried: %s\n", font.triedList().c_str());
    return exit_code::MISSING_RESOURCE;
  }
  // A script with a mistake stops the run before a window opens (UsageError,
  // exit status 2).
  std::vector<ScriptEvent> script = loadScript(options);

  try {
    // Declared in this order so GL objects go before the context they live in.
    GlWindow window(first.title(), options.width, options.height, options.vsync);
    Views views(shaders.found, font.found, window, options);
    // One script for the whole window; after a switch its frame numbers
    // count the new scene's frames from 1.
    EventPlayer player(std::move(script), window.sdlWindow());
    AbstractWindow* scene = &first;
    for (;;) {
      // Built only now that the window can run, so that a refused window run
      // (no display, unusable shaders or font) leaves no output file behind;
      // a runner that built it already is fine too.
      if (!scene->world()) scene->initialize(options);
      FrameLoop loop(*scene, options, window, views, player);
      const int status = loop.run();
      if (!next || scene->switchRequest() == 0 || stopSignal() != 0) return status;
      scene = &next(scene->switchRequest());
      SDL_SetWindowTitle(window.sdlWindow(), scene->title().c_str());
    }
  } catch (const NoDisplayError& error) {
    std::fprintf(stderr, "error: cannot open a window (%s); set DISPLAY or run with --headless\n", error.what());
    return exit_code::NO_DISPLAY;
  } catch (const ResourceError& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return exit_code::MISSING_RESOURCE;
  } catch (const RenderError& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return exit_code::RUNTIME_ERROR;
  }
}

}  // namespace odelab
