#pragma once

// MJCF in: a MuJoCo model file read by MuJoCo's own loader (mj_loadXML) and
// turned into this format's world description (doc/world-format.md, "MJCF"),
// so that every engine, ODE's included, runs it as it runs a .json world.
// What the format cannot hold is refused (WorldFileError, status 2) when it
// changes the mechanics, and otherwise named once in World::notes.
// A build without MuJoCo compiles WorldFromMjcfAbsent.cpp instead, which
// refuses every MJCF file saying so.

#include <string>

#include "WorldDescription.h"

namespace odelab::world {

// Whether a file is MJCF rather than JSON: its name ends in ".xml", or its
// text starts (after blanks and an XML declaration) with "<mujoco".
bool looksLikeMjcf(const std::string& path, const std::string& text);

// Throws WorldFileError naming the path, with MuJoCo's own text when MuJoCo
// refused the file, or the element the format cannot hold.
World worldFromMjcf(const std::string& path);

}  // namespace odelab::world
