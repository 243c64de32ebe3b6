#pragma once

// The adapters this library holds, each in its own file; EngineCatalog.cpp
// lists those that were built.

#include <memory>
#include <string>
#include <vector>

#include "world/EngineCatalog.h"

namespace odelab::engines {

world::EngineInfo bulletInfo();
std::unique_ptr<world::Engine> makeBullet(world::EngineSetting setting);

world::EngineInfo mujocoInfo();
std::unique_ptr<world::Engine> makeMujoco(world::EngineSetting setting);

// Havok, Jolt, Rapier and PhysX (WasmEngines.h), each in Node.js (peers/wasm/engine_server.js) ...
world::EngineInfo nodeEngineInfo(const std::string& name);  // asks node whether it is there
std::unique_ptr<world::Engine> makeNodeEngine(const std::string& name, world::EngineSetting setting);
// ... or, in the browser build, in the page (web/engines/).
world::EngineInfo browserEngineInfo(const std::string& name);  // asks the page whether it loaded it
std::unique_ptr<world::Engine> makeBrowserEngine(const std::string& name, world::EngineSetting setting);

// What main() installs (world::installEngineCatalog).
world::EngineCatalog catalog();

}  // namespace odelab::engines
