#pragma once

// Where a value sits in a JSON text, by its path: so that an error in a world
// file can name the line as well as the field ("line 12: bodies[0].mass").
// nlohmann-json 3.11 (Debian 12's) keeps no positions in its values, refuses
// no duplicate key (it keeps the last) and says a missing comma at the token
// after it; this one pass over the text does all three, in time and memory
// linear in the text: the stack of open arrays and objects is bounded by
// MAX_JSON_DEPTH, and a path is spelt out only when something is reported.
// The world reader makes this pass only for a text it refuses: a text that
// reads needs no line (JsonDocument.h reads it, and notes what this pass places).

#include <string>

namespace odelab::world {

// Deeper than any world file needs (it nests four deep: world, bodies, a body,
// its auto_disable): the bound that keeps the scan's stack, and nlohmann's, small.
constexpr int MAX_JSON_DEPTH = 64;

// What one pass found wrong in the text's shape (each: the first of its kind, 0 when none).
struct JsonShape {
  int tooDeepLine = 0;          // where an array or object opens past MAX_JSON_DEPTH
  int duplicateLine = 0;        // where a key is given a second time in one object
  std::string duplicatePath;    // that key's path ("bodies[1].mass")
  int missingLine = 0;          // where a value ends that is followed by neither ',' nor its closer
  std::size_t missingAt = 0;    // the offset of what follows it instead
  std::string missingAfter;     // the value as written ("\"version\": 1"), cut to one short line
  char missingCloser = '}';     // the closer its array or object wanted
};

// A leading UTF-8 byte-order mark is skipped, as nlohmann skips it.
JsonShape scanJsonShape(const std::string& text);

// The 1-based line where the value at `path` starts ("bodies[0].mass",
// "settings"); the nearest enclosing value's line when the path itself is
// absent (a missing field: its object's line); 0 when none is found.
int lineOfPath(const std::string& text, const std::string& path);

}  // namespace odelab::world
