// The window side's two entry points for the runner (WindowEntry.h): as the
// module's one exported symbol where it is loaded at run time, or as
// windowEntry() where it is linked in.
#include "../WindowEntry.h"

#include "WindowFrontend.h"

namespace {
const odelab::WindowEntry entry{&odelab::runWindow, &odelab::runWindowSwitching};
}  // namespace

#ifdef ODELAB_WINDOW_MODULE
extern "C" __attribute__((visibility("default"))) const odelab::WindowEntry* odelab_window_entry() { return &entry; }
#else
const odelab::WindowEntry* odelab::windowEntry() { return &entry; }
#endif
