#include "SpaceKind.h"

namespace odelab {

const char* spaceKindName(SpaceKind kind) {
  switch (kind) {
    case SpaceKind::Simple: return "simple";
    case SpaceKind::Hash: return "hash";
    case SpaceKind::SweepAndPrune: return "sap";
    case SpaceKind::QuadTree: return "quadtree";
  }
  return "?";
}

bool parseSpaceKind(const std::string& text, SpaceKind& kind) {
  for (SpaceKind candidate : {SpaceKind::Simple, SpaceKind::Hash, SpaceKind::SweepAndPrune, SpaceKind::QuadTree})
    if (text == spaceKindName(candidate)) {
      kind = candidate;
      return true;
    }
  return false;
}

}  // namespace odelab
