#pragma once

// Which engines a program can run its scene on (--engine, --list-engines).
// The adapters live in peers/ (the odelab_engines library); a program's
// main() installs their catalog here before it runs, so the framework
// reaches them without depending on them (checks that build scenes in
// process run ODE alone).

#include <memory>
#include <string>
#include <vector>

#include "Engine.h"

namespace odelab::world {

struct EngineInfo {
  std::string name;     // "bullet": what --engine takes
  std::string version;  // "3.24", or "" where unknown
  bool available = false;
  std::string missing;  // why it is not here and how to install it ("" when available)
  std::string precision;  // "double" or "float32"
  std::string bestSettings;  // what --engine-setting best changes, in words
};

struct EngineCatalog {
  std::vector<EngineInfo> (*list)() = nullptr;
  // Throws EngineError naming the engine and why when it cannot be made.
  std::unique_ptr<Engine> (*make)(const std::string& name, EngineSetting setting) = nullptr;
};

void installEngineCatalog(const EngineCatalog& catalog);
// Every engine the program knows ("ode" first, built in); only "ode" where none was installed.
std::vector<EngineInfo> knownEngines();
std::unique_ptr<Engine> makeEngine(const std::string& name, EngineSetting setting);

}  // namespace odelab::world
