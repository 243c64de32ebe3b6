#pragma once

#include <functional>

#include "../AbstractWindow.h"
#include "../CompareLanes.h"

namespace odelab {

// Opens an SDL2 window with an OpenGL 3.3 core context and runs the frame
// loop: events go to the scene's key table and camera, the elapsed real time
// goes to scene.advanceFrame(), and the scene is drawn with shadow mapping
// and the HUD. Returns an exit status from ExitCodes.h (NO_DISPLAY when no
// window can be opened, MISSING_RESOURCE when shaders or font are not found or unusable).
// The --events script (and its key names) is read before the window opens;
// a mistake throws UsageError naming the file and line (exit status 2).
// Unless the caller did, it builds the scene (scene.initialize) once the
// window, shaders, font and script are ready, so a refused run writes nothing.
// What the run's status goes through once the window is done (`finish`):
// in a browser the frames are called back after this function has left, so
// the caller's closing steps come as this callback, and runWindow returns
// what it returns.
int runWindow(AbstractWindow& scene, const RunOptions& options, const std::function<int(int)>& finish);

// The launcher's window: runs `first` as runWindow does, and when the scene
// ends asking for another (AbstractWindow::switchRequest), runs the one
// `next(direction)` gives in the same window, built with the same options.
// `next` ends and destroys the scene it replaces (its files, locks and
// hooks released) before it makes the next; it returns the scene now
// running. Requests of one frame add up (two Page Ups: two scenes back).
// --record numbers frames over the whole window, every scene's; --events
// frame numbers count each scene's frames from 1. `finish` gets the status
// as with runWindow. A browser page runs one scene: there `next` is not used.
int runWindowSwitching(AbstractWindow& first, const RunOptions& options,
                       const std::function<AbstractWindow&(int direction)>& next,
                       const std::function<int(int)>& finish);

// The compare window (--compare without --headless; doc/manual.md,
// "Engines side by side"): runs the lanes' lead, ODE's scene, as runWindow
// does, with every other lane's scene (another engine's each) built beside
// it and following it step for step, each in a view of its own under one
// camera. `finish` gets the status as with runWindow.
int runCompareWindow(CompareLanes& lanes, const RunOptions& options, const std::function<int(int)>& finish);

// Reads and checks the --events script only, throwing UsageError like
// runWindow. For the runner to call before the scene is built, so that a bad
// script stops the run before any output file is written.
void checkWindowOptions(const RunOptions& options);

}  // namespace odelab
