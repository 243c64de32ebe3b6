#pragma once

// Where a value sits in a JSON text, by its path: so that an error in a world
// file can name the line as well as the field ("line 12: bodies[0].mass").
// nlohmann-json 3.11 (Debian 12's) keeps no positions in its values; this
// walks text that nlohmann has already parsed, so it need not handle errors.

#include <string>

namespace odelab::world {

// The 1-based line where the value at `path` starts ("bodies[0].mass",
// "settings"); the nearest enclosing value's line when the path itself is
// absent (a missing field: its object's line); 0 when none is found.
int lineOfPath(const std::string& text, const std::string& path);

}  // namespace odelab::world
