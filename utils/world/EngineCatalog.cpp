#include "EngineCatalog.h"

#include <ode/ode.h>

namespace odelab::world {

namespace {
EngineCatalog& installed() {
  static EngineCatalog catalog;
  return catalog;
}
}  // namespace

void installEngineCatalog(const EngineCatalog& catalog) { installed() = catalog; }

std::vector<EngineInfo> knownEngines() {
  EngineInfo ode;
  ode.name = "ode";
  ode.available = true;
  ode.precision = sizeof(dReal) == 8 ? "double" : "single";
  ode.bestSettings = "the scene's own settings (--engine-setting is for the other engines; the atlas's ODE best is --solver step)";
  std::vector<EngineInfo> engines{ode};
  if (installed().list)
    for (EngineInfo& info : installed().list()) engines.push_back(std::move(info));
  return engines;
}

std::unique_ptr<Engine> makeEngine(const std::string& name, EngineSetting setting) {
  if (!installed().make) throw EngineError("engine '" + name + "': this program was built without the engine adapters");
  return installed().make(name, setting);
}

}  // namespace odelab::world
