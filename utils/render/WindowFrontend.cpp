#include "WindowFrontend.h"

#include <cstdio>

#include "../ExitCodes.h"
#include "../ResourcePaths.h"
#include "GlWindow.h"
#include "HudText.h"
#include "Renderer.h"
#include "Screenshot.h"
#include "WindowInput.h"

namespace odelab {

namespace {

const double FPS_AVERAGING_SECONDS = 0.5;
// Frames are paced to at most 125 per second: short enough that no frame
// exceeds the fixed-step loop's 10 ms clamp (so the simulation keeps real
// time on a machine that can draw that fast), long enough not to spin.
const double FRAME_PERIOD = 0.008;

// Frames per second, averaged over about half a second so the HUD is readable.
class FrameRateMeter {
 public:
  // Returns true when a new average is ready in fps().
  bool addFrame(double seconds) {
    ++frames_;
    seconds_ += seconds;
    if (seconds_ < FPS_AVERAGING_SECONDS) return false;
    fps_ = frames_ / seconds_;
    frames_ = 0;
    seconds_ = 0.0;
    return true;
  }
  double fps() const { return fps_; }

 private:
  int frames_ = 0;
  double seconds_ = 0.0;
  double fps_ = 0.0;
};

bool finished(const AbstractWindow& scene, const RunOptions& options) {
  return scene.quitRequested() || (options.seconds > 0.0 && scene.simulatedTime() >= options.seconds);
}

int runLoop(AbstractWindow& scene, const RunOptions& options, GlWindow& window, Renderer& renderer, HudText& hud) {
  const bool screenshotRun = !options.screenshot.empty();
  const int screenshotFrame = options.frames > 0 ? options.frames : 1;
  const double ticksPerSecond = static_cast<double>(SDL_GetPerformanceFrequency());
  Uint64 previous = SDL_GetPerformanceCounter();
  FrameRateMeter meter;

  for (int frame = 1; !finished(scene, options); ++frame) {
    SDL_Event event;
    while (SDL_PollEvent(&event))
      if (handleEvent(event, scene)) window.updateDrawableSize();
    syncMouseLook(scene);

    const Uint64 now = SDL_GetPerformanceCounter();
    const double elapsed = static_cast<double>(now - previous) / ticksPerSecond;
    previous = now;
    moveCamera(scene, elapsed);
    scene.advanceFrame(elapsed);  // an OdeError leaves through here; RAII cleans up
    if (meter.addFrame(elapsed)) scene.setFramesPerSecond(meter.fps());

    renderer.render(scene, window.width(), window.height());
    if (scene.hudVisible()) hud.draw(scene.hudLines(), window.width(), window.height());

    // Read the back buffer before the swap leaves its contents undefined.
    if (screenshotRun && frame == screenshotFrame) {
      saveScreenshot(options.screenshot, window.width(), window.height());
      std::printf("screenshot: %s (%dx%d, frame %d)\n", options.screenshot.c_str(), window.width(),
                  window.height(), frame);
      return exit_code::OK;
    }
    window.swap();
    const double frameSeconds = static_cast<double>(SDL_GetPerformanceCounter() - now) / ticksPerSecond;
    if (frameSeconds < FRAME_PERIOD) SDL_Delay(static_cast<Uint32>((FRAME_PERIOD - frameSeconds) * 1000.0));
  }
  return exit_code::OK;
}

}  // namespace

int runWindow(AbstractWindow& scene, const RunOptions& options) {
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

  try {
    // Declared in this order so GL objects go before the context they live in.
    GlWindow window(scene.title(), options.width, options.height);
    Renderer renderer(shaders.found);
    HudText hud(font.found, shaders.found);
    return runLoop(scene, options, window, renderer, hud);
  } catch (const NoDisplayError& error) {
    std::fprintf(stderr, "error: cannot open a window (%s); set DISPLAY or run with --headless\n", error.what());
    return exit_code::NO_DISPLAY;
  } catch (const RenderError& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return exit_code::RUNTIME_ERROR;
  }
}

}  // namespace odelab
