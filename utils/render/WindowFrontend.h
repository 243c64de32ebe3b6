#pragma once

#include "../AbstractWindow.h"

namespace odelab {

// Opens an SDL2 window with an OpenGL 3.3 core context and runs the frame
// loop: events go to the scene's key table and camera, the elapsed real time
// goes to scene.advanceFrame(), and the scene is drawn with shadow mapping
// and the HUD. Returns an exit status from ExitCodes.h (NO_DISPLAY when no
// window can be opened, MISSING_RESOURCE when shaders or font are not found).
int runWindow(AbstractWindow& scene, const RunOptions& options);

}  // namespace odelab
