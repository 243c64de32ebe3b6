#pragma once

// The reader's message for a world text it refuses, or "(accepted)": what
// the world-file tests compare their refusals with.

#include <string>

#include "world/WorldJson.h"

inline std::string worldFileErrorOf(const std::string& text) {
  try {
    odelab::world::worldFromJson(text);
  } catch (const odelab::world::WorldFileError& error) {
    return error.what();
  }
  return "(accepted)";
}
