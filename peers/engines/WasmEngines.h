#pragma once

// Havok, Jolt, Rapier and PhysX: the engines whose builds here are WebAssembly
// (peers/wasm/src/engines/), run by Node.js on the desktop and by the page
// in the browser. This table is the one list of them on the C++ side; every
// build has it, so that --list-engines names them even where none can run.

#include <string>
#include <vector>

#include "world/EngineCatalog.h"

namespace odelab::engines {

struct WasmEngineKind {
  const char* name;     // on the command line: "jolt"
  const char* title;    // in messages: "Jolt"
  const char* package;  // the npm package
  const char* best;     // what --engine-setting best changes (src/engines/<name>.js says why)
};

const std::vector<WasmEngineKind>& wasmEngineKinds();
const WasmEngineKind* wasmEngineKind(const std::string& name);  // nullptr when not one of them
std::vector<std::string> wasmEngineNames();
std::string wasmEngineList();  // "havok, jolt, rapier, physx", for messages
// What --list-engines says of every one of them wherever it runs: its name,
// float32 and its best settings; `missing` says so when `name` is not one.
world::EngineInfo wasmEngineInfo(const std::string& name);

}  // namespace odelab::engines
