#pragma once

#include <string>

namespace odelab {

// The collision spaces ODE offers; a scene starts with one and Q cycles them.
enum class SpaceKind { Simple, Hash, SweepAndPrune, QuadTree };
const char* spaceKindName(SpaceKind kind);  // "simple", "hash", "sap", "quadtree"
bool parseSpaceKind(const std::string& text, SpaceKind& kind);

}  // namespace odelab
