#include "WasmEngines.h"

namespace odelab::engines {

const std::vector<WasmEngineKind>& wasmEngineKinds() {
  static const std::vector<WasmEngineKind> kinds{
      {"havok", "Havok", "@babylonjs/havok",
       "the solver tuned for the world's step (ideal step time h, not 1/60 s), no damping (default angular 0.1), "
       "speed caps raised out of reach (default 200 m/s, 100 rad/s)"},
      {"jolt", "Jolt", "jolt-physics",
       "no damping (default 0.05 linear and angular), 50 velocity and 10 position iterations (default 10 and 2), "
       "restitution from the world's bounce velocity (default: none below 1 m/s), speed caps out of reach "
       "(default 500 m/s, 47 rad/s), swept motion (LinearCast) for every moving body"},
      {"rapier", "Rapier", "@dimforge/rapier3d-compat",
       "50 solver iterations (default 4), continuous collision (CCD) for every moving body, the speed cap "
       "(400 m/s x lengthUnit) out of reach: lengthUnit 1000 with its length tolerances divided by 1000"},
      {"physx", "PhysX", "physx-js-webidl",
       "the TGS solver (default PGS) with 32 position and 4 velocity iterations per body (default 4 and 1), no "
       "damping (default angular 0.05), speed caps out of reach (default 100 rad/s), restitution from the world's "
       "bounce velocity (default: none below 2 m/s), swept CCD for every moving body"},
  };
  return kinds;
}

const WasmEngineKind* wasmEngineKind(const std::string& name) {
  for (const WasmEngineKind& kind : wasmEngineKinds())
    if (name == kind.name) return &kind;
  return nullptr;
}

std::string wasmEngineList() {
  std::string list;
  for (const WasmEngineKind& kind : wasmEngineKinds()) list += (list.empty() ? "" : ", ") + std::string(kind.name);
  return list;
}

std::vector<std::string> wasmEngineNames() {
  std::vector<std::string> names;
  for (const WasmEngineKind& kind : wasmEngineKinds()) names.push_back(kind.name);
  return names;
}

world::EngineInfo wasmEngineInfo(const std::string& name) {
  world::EngineInfo info;
  info.name = name;
  info.precision = "float32";
  if (const WasmEngineKind* kind = wasmEngineKind(name)) info.bestSettings = kind->best;
  else info.missing = "not one of " + wasmEngineList();
  return info;
}

}  // namespace odelab::engines
