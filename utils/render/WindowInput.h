#pragma once

#include <SDL2/SDL.h>

#include "../AbstractWindow.h"

namespace odelab {

// Turns SDL input into scene actions: Esc and closing the window quit, the
// left button toggles mouse-look, mouse motion turns the camera while it is
// on, and every other key press goes to the scene's key table.
// Returns true when the window's drawable size may have changed.
bool handleEvent(const SDL_Event& event, AbstractWindow& scene);

// Flies the camera with W/S/A/D held, read from the keyboard state each
// frame so movement is smooth rather than paced by key repeat.
void moveCamera(AbstractWindow& scene, double frameSeconds);

// Keeps SDL's relative mouse mode (hidden, captured cursor) in step with the
// scene's mouse-look flag, whoever changed it.
void syncMouseLook(const AbstractWindow& scene);

}  // namespace odelab
