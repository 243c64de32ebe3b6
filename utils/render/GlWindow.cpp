#include "GlWindow.h"

#include <GL/glew.h>

#include <cstring>

namespace odelab {

namespace {

void requestCoreContext(int multisamples) {
#ifdef __EMSCRIPTEN__
  // OpenGL ES 3.0, which the browser gives as WebGL2.
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_ES);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 0);
#else
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
#endif
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
  SDL_GL_SetAttribute(SDL_GL_MULTISAMPLEBUFFERS, multisamples > 0 ? 1 : 0);
  SDL_GL_SetAttribute(SDL_GL_MULTISAMPLESAMPLES, multisamples);
}

// SDL falls back to drivers that open no visible window when there is no
// display; a window nobody sees is not what the user asked for. Asking for
// one by name (SDL_VIDEODRIVER=offscreen) is still allowed.
void refuseInvisibleFallback() {
  const char* driver = SDL_GetCurrentVideoDriver();
  const char* requested = SDL_getenv("SDL_VIDEODRIVER");
  const bool invisible = driver && (std::strcmp(driver, "offscreen") == 0 || std::strcmp(driver, "dummy") == 0);
  if (invisible && !(requested && *requested))
    throw NoDisplayError(std::string("no display found; SDL offers only its '") + driver + "' driver");
}

// glGetString is OpenGL 1.0, there without GLEW.
bool isSoftwareRenderer() {
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!renderer) return false;
  for (const char* name : {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer"})
    if (std::strstr(renderer, name)) return true;
  return false;
}

}  // namespace

GlWindow::VideoSubsystem::VideoSubsystem() {
  // SDL would turn SIGINT and SIGTERM into a window close, which ends the
  // run as if complete (status 0); the program handles them (StopSignal.h).
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
#if defined(__linux__) && !defined(__EMSCRIPTEN__)
  // With neither display named (DISPLAY= included), SDL would try each of
  // its drivers and print its own complaints (Wayland's "XDG_RUNTIME_DIR is
  // invalid or not set") before ours: said here first, and only ours.
  const auto unset = [](const char* name) {
    const char* value = SDL_getenv(name);
    return !value || !*value;
  };
  if (unset("DISPLAY") && unset("WAYLAND_DISPLAY") && unset("SDL_VIDEODRIVER"))
    throw NoDisplayError("no display found (DISPLAY and WAYLAND_DISPLAY are not set)");
#endif
  if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) throw NoDisplayError(SDL_GetError());
  try {
    refuseInvisibleFallback();
  } catch (...) {
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    throw;
  }
}

GlWindow::GlWindow(const std::string& title, int width, int height, bool vsync) {
  const Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI;
  // Antialiased edges when the driver offers them in hardware; plain
  // otherwise (a software renderer would store and shade every sample).
  for (int multisamples : {4, 0}) {
    requestCoreContext(multisamples);
    window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height, flags);
    if (!window_) continue;
    context_ = SDL_GL_CreateContext(window_);
    if (context_) {
      software_ = isSoftwareRenderer();
      if (!(software_ && multisamples > 0)) break;
      SDL_GL_DeleteContext(context_);
      context_ = nullptr;
    }
    SDL_DestroyWindow(window_);
    window_ = nullptr;
  }
  if (!window_ || !context_) throw NoDisplayError(SDL_GetError());

  // GLEW looks functions up through the old glGetString(GL_EXTENSIONS),
  // which a core profile lacks; experimental mode makes it query them all.
  glewExperimental = GL_TRUE;
  const GLenum status = glewInit();
  // glewInit can leave a harmless GL_INVALID_ENUM behind; clear it.
  glGetError();
  // Without GLX (an EGL context, as SDL's offscreen driver makes) GLEW still
  // loads every GL function and only reports the missing GLX display.
  if (status != GLEW_OK && status != GLEW_ERROR_NO_GLX_DISPLAY) {
    const std::string reason = reinterpret_cast<const char*>(glewGetErrorString(status));
    SDL_GL_DeleteContext(context_);
    SDL_DestroyWindow(window_);
    throw RenderError("cannot load OpenGL functions (GLEW: " + reason + ")");
  }
  // Vsync where the driver offers it; the frame loop's cap paces frames
  // where it does not (a software renderer under Xvfb has no refresh).
  vsync_ = vsync && SDL_GL_SetSwapInterval(1) == 0;
  if (!vsync_) SDL_GL_SetSwapInterval(0);
  updateDrawableSize();
}

GlWindow::~GlWindow() {
  SDL_GL_DeleteContext(context_);
  SDL_DestroyWindow(window_);
}

}  // namespace odelab
