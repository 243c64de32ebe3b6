#pragma once

#include <functional>

#include "AbstractWindow.h"
#include "CompareLanes.h"
#include "RunOptions.h"

namespace odelab {

// The window side (utils/render/) as the runner reaches it: runWindow,
// runWindowSwitching and runCompareWindow of render/WindowFrontend.h. Where the programs load
// the window side as a module only when a window is asked for (Linux), a
// headless run never maps SDL, OpenGL, GLEW, ImGui or the font libraries;
// elsewhere (Windows, the browser) it is linked in and this is a table of
// its two functions.
struct WindowModule {
  int (*run)(AbstractWindow& scene, const RunOptions& options, const std::function<int(int)>& finish);
  int (*runSwitching)(AbstractWindow& first, const RunOptions& options,
                      const std::function<AbstractWindow&(int direction)>& next,
                      const std::function<int(int)>& finish);
  int (*runCompare)(CompareLanes& lanes, const RunOptions& options, const std::function<int(int)>& finish);
};

// The window side, loaded on the first call where it is a module; null
// after printing an error that names the module and why it did not load.
const WindowModule* windowModule();

}  // namespace odelab
