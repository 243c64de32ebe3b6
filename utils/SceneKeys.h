#pragma once

#include <string>
#include <vector>

#include "KeyTable.h"

namespace odelab {

// The keys a scene binds for itself (spawn, drop, throw, launch, its own
// value on F5, a space or CCD switch, and R where the scene gave it another
// action than reset), in the table's order: what the compact HUD names and
// the panel puts on buttons.
std::vector<const KeyBinding*> sceneKeys(const KeyTable& keys);

// "N: drop a plate ..." shortened to its first clause (up to " (" or ";").
std::string shortKeyText(const KeyBinding& binding);

}  // namespace odelab
