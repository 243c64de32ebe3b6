// Havok, Jolt, Rapier and PhysX run in Node.js, through their npm WebAssembly
// builds: each engine is a child process (peers/wasm/engine_server.js)
// spoken to over its pipes in JSON lines (doc/engine-protocol.md,
// ProtocolEngine.cpp). Its stderr is the program's.
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "Adapters.h"
#include "EnginePipe.h"
#include "ProtocolEngine.h"
#include "WasmEngines.h"

namespace odelab::engines {

namespace {

using nlohmann::json;

// node: $ODELAB_NODE, else what CMake found.
std::string nodeProgram() {
  if (const char* env = std::getenv("ODELAB_NODE"); env && *env) return env;
  const std::string found = ODELAB_NODE_PROGRAM;
  if (found.empty() || found.find("NOTFOUND") != std::string::npos) return "node";
  return found;
}

bool executable(const std::string& program) {
  if (program.find('/') != std::string::npos) return ::access(program.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  return false;
}

std::string serverPath() { return ODELAB_ENGINE_SERVER; }

std::string wasmDirectory() {
  const std::string server = serverPath();
  return server.substr(0, server.find_last_of('/'));
}

// The installed package's version ("" when it is not installed).
std::string packageVersion(const WasmEngineKind& kind) {
  std::ifstream file(wasmDirectory() + "/node_modules/" + kind.package + "/package.json");
  if (!file) return "";
  try {
    const json package = json::parse(file);
    return package.value("version", "?");
  } catch (const json::exception&) {
    return "";
  }
}

const std::string INSTALL = "install Node.js (Debian's nodejs) and run `npm ci` in peers/wasm";

// The child's pipes as the protocol's link.
class PipeLink : public ProtocolLink {
 public:
  explicit PipeLink(const std::vector<std::string>& argv) : pipe_(argv) {}
  bool writeLine(const std::string& line) override { return pipe_.writeLine(line); }
  bool readLine(std::string& line) override { return pipe_.readLine(line); }
  std::string endedHow() override { return pipe_.endedHow() + "; its messages are above on stderr"; }
  void setDeadline(double seconds) override { pipe_.setDeadline(seconds); }

 private:
  EnginePipe pipe_;  // its destructor closes the pipe and waits for the child
};

}  // namespace

world::EngineInfo nodeEngineInfo(const std::string& name) {
  world::EngineInfo info = wasmEngineInfo(name);
  if (!info.missing.empty()) return info;
  const WasmEngineKind* kind = wasmEngineKind(name);
  const std::string node = nodeProgram();
  if (!executable(node)) {
    info.missing = "Node.js (" + node + ") not found: " + INSTALL;
    return info;
  }
  if (::access(serverPath().c_str(), R_OK) != 0) {
    info.missing = serverPath() + " not found";
    return info;
  }
  info.version = packageVersion(*kind);
  if (info.version.empty()) {
    info.missing = std::string("the npm package ") + kind->package + " is not installed: " + INSTALL;
    return info;
  }
  info.available = true;
  return info;
}

std::unique_ptr<world::Engine> makeNodeEngine(const std::string& name, world::EngineSetting setting) {
  const WasmEngineKind* kind = wasmEngineKind(name);
  if (!kind) throw world::EngineError("'" + name + "' is not one of " + wasmEngineList());
  const std::vector<std::string> argv{nodeProgram(), "--no-concurrent-recompilation", serverPath(), kind->name,
                                      setting == world::EngineSetting::Best ? "best" : "default"};
  std::unique_ptr<ProtocolLink> link;
  try {
    link = std::make_unique<PipeLink>(argv);
  } catch (const std::exception& error) {
    throw world::EngineFailure(std::string(kind->title) + ": " + error.what() + " (" + INSTALL + ")");
  }
  return makeProtocolEngine(kind->title, "Node.js engine server", std::move(link));
}

}  // namespace odelab::engines
