#include "WebMainLoop.h"

#include <emscripten.h>

#include <cstdio>
#include <exception>

#include "../ExitCodes.h"

namespace odelab::web {

namespace {

struct Callbacks {
  std::function<bool()> frame;
  std::function<int()> done;
};
Callbacks* active = nullptr;

// The page learns the end from here: it shows the status and lists the
// files the run wrote for download. The runtime is kept alive: ending it
// (as a cancelled main loop otherwise does) would close the window and
// clear the canvas, the run's last picture.
EM_JS(void, announceEnd, (int status), {
  runtimeKeepalivePush();
  if (Module["onRunEnd"]) Module["onRunEnd"](status);
});

void end(int status) {
  emscripten_cancel_main_loop();
  std::fflush(stdout);
  std::fflush(stderr);
  announceEnd(status);
}

void callFrame(void*) {
  int status = exit_code::OK;
  try {
    if (active->frame()) return;
    status = active->done();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    status = exit_code::RUNTIME_ERROR;
  }
  end(status);
}

}  // namespace

void runEveryFrame(std::function<bool()> frame, std::function<int()> done) {
  active = new Callbacks{std::move(frame), std::move(done)};
  // 0: at the browser's own pace (requestAnimationFrame); 1: this call
  // unwinds the stack instead of returning.
  emscripten_set_main_loop_arg(callFrame, nullptr, 0, 1);
  __builtin_unreachable();
}

}  // namespace odelab::web
