#pragma once

// SDF in: a Gazebo world (SDFormat) read by SDFormat's own parser
// (sdf::Root::Load) and turned into this format's world description
// (doc/world-format.md, "SDF"), so that every engine, ODE's included, runs it
// as it runs a .json world. What the format cannot hold is refused
// (WorldFileError, status 2) when it changes the mechanics, and otherwise
// named once in World::notes. A build without SDFormat compiles
// WorldFromSdfAbsent.cpp instead, which refuses every SDF file saying so.

#include <string>

#include "WorldDescription.h"

namespace odelab::world {

// Whether a file is SDF: its name ends in ".sdf" or ".world", or its text
// starts (after blanks, an XML declaration and comments) with "<sdf".
bool looksLikeSdf(const std::string& path, const std::string& text);

// Throws WorldFileError naming the path, with SDFormat's own text when it
// refused the file, or the element the format cannot hold.
World worldFromSdf(const std::string& path);

}  // namespace odelab::world
