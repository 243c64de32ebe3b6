#pragma once

#include <functional>

namespace odelab::web {

// The browser's frame loop: `frame` is called once per animation frame
// (requestAnimationFrame) until it returns false; then `done` runs once and
// the page is told the run ended with the status it returns (Module.onRunEnd
// in web/odelab.js). An exception from either ends the run with status 1,
// its message on stderr. Does not return: the caller's stack is left as it
// is, so what the callbacks use must outlive it (heap, or the frames of
// main's callers that stay).
[[noreturn]] void runEveryFrame(std::function<bool()> frame, std::function<int()> done);

}  // namespace odelab::web
