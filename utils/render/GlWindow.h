#pragma once

#include <SDL2/SDL.h>

#include <string>

#include "RenderError.h"

namespace odelab {

// No window could be opened (no display, no GL 3.3): runWindow turns this
// into exit_code::NO_DISPLAY rather than a generic failure.
class NoDisplayError : public RenderError {
 public:
  using RenderError::RenderError;
};

// SDL's video subsystem, one resizable window and its OpenGL 3.3 core
// context with GLEW loaded; all released in reverse order on destruction.
class GlWindow {
 public:
  // Throws NoDisplayError with SDL's reason, or RenderError if GLEW fails.
  // `vsync`: ask the driver to wait for the display's refresh at each swap.
  GlWindow(const std::string& title, int width, int height, bool vsync = true);
  ~GlWindow();
  GlWindow(const GlWindow&) = delete;
  GlWindow& operator=(const GlWindow&) = delete;

  // Size of the GL drawable in pixels; re-read after SDL_WINDOWEVENT_SIZE_CHANGED.
  void updateDrawableSize() { SDL_GL_GetDrawableSize(window_, &width_, &height_); }
  int width() const { return width_; }
  int height() const { return height_; }
  void swap() { SDL_GL_SwapWindow(window_); }
  bool vsync() const { return vsync_; }  // granted by the driver
  // The renderer draws on the CPU (Mesa's llvmpipe or softpipe, SwiftShader):
  // every pixel costs, so the window opens without multisampling and the
  // renderer takes its cheaper shadow filter.
  bool software() const { return software_; }
  void* glContext() const { return context_; }
  // Size in window coordinates, those of mouse events (differs from the
  // drawable size on high-DPI screens).
  void windowSize(int& width, int& height) const { SDL_GetWindowSize(window_, &width, &height); }
  SDL_Window* sdlWindow() const { return window_; }

 private:
  struct VideoSubsystem {
    VideoSubsystem();
    ~VideoSubsystem() { SDL_QuitSubSystem(SDL_INIT_VIDEO); }
  };

  VideoSubsystem video_;
  SDL_Window* window_ = nullptr;
  bool vsync_ = false;
  bool software_ = false;
  SDL_GLContext context_ = nullptr;
  int width_ = 0, height_ = 0;
};

}  // namespace odelab
