// The window side's entry points for the runner (WindowModule.h): as the
// module's one exported symbol where it is loaded at run time, or as
// windowModule() where it is linked in.
#include "../WindowModule.h"

#include "WindowFrontend.h"

namespace {
const odelab::WindowModule entry{&odelab::runWindow, &odelab::runWindowSwitching, &odelab::runCompareWindow};
}  // namespace

#ifdef ODELAB_WINDOW_MODULE
extern "C" __attribute__((visibility("default"))) const odelab::WindowModule* odelab_window_module() { return &entry; }
#else
const odelab::WindowModule* odelab::windowModule() { return &entry; }
#endif
