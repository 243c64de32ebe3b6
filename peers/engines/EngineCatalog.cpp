#include "Adapters.h"
#include "WasmEngines.h"

namespace odelab::engines {

namespace {

#ifdef __EMSCRIPTEN__
constexpr bool BROWSER = true;
#else
constexpr bool BROWSER = false;
#endif

// The engines other than ODE in the order --list-engines prints them, each
// whether or not it was built, so that a missing one is named with its cure.
const std::vector<std::string>& engineNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all{"bullet", "mujoco"};
    for (const std::string& name : wasmEngineNames()) all.push_back(name);
    return all;
  }();
  return names;
}

std::string engineList() {
  std::string list = "ode";
  for (const std::string& name : engineNames()) list += ", " + name;
  return list;
}

[[maybe_unused]] world::EngineInfo notBuilt(const std::string& name, const std::string& why) {
  world::EngineInfo info;
  info.name = name;
  info.missing = why;
  return info;
}

#if defined(ODELAB_ENGINE_NODE) || defined(ODELAB_ENGINE_BROWSER)
bool isWasmEngine(const std::string& name) { return wasmEngineKind(name) != nullptr; }
#endif

world::EngineInfo infoOf(const std::string& name) {
  if (name == "bullet") {
#ifdef ODELAB_ENGINE_BULLET
    return bulletInfo();
#else
    return notBuilt(name, BROWSER ? "the browser build has no Bullet: its adapter is C++ on Debian's native library"
                                  : "this build has no Bullet: install Debian's libbullet-dev and configure again");
#endif
  }
  if (name == "mujoco") {
#ifdef ODELAB_ENGINE_MUJOCO
    return mujocoInfo();
#else
    return notBuilt(name, BROWSER ? "the browser build has no MuJoCo: its adapter is C++ on Debian's native library, "
                                    "and MuJoCo's WebAssembly build (npm mujoco-js) has no adapter yet"
                                  : "this build has no MuJoCo: install Debian's libmujoco-dev and libqhull-dev and "
                                    "configure again");
#endif
  }
#if defined(ODELAB_ENGINE_NODE)
  return nodeEngineInfo(name);
#elif defined(ODELAB_ENGINE_BROWSER)
  return browserEngineInfo(name);
#else
  return notBuilt(name, "this build cannot start Node.js engines (the Windows build runs ODE alone)");
#endif
}

std::vector<world::EngineInfo> list() {
  std::vector<world::EngineInfo> engines;
  for (const std::string& name : engineNames()) engines.push_back(infoOf(name));
  return engines;
}

std::unique_ptr<world::Engine> make(const std::string& name, world::EngineSetting setting) {
  const world::EngineInfo info = infoOf(name);
  if (!info.available) throw world::EngineError("engine '" + name + "' is not available here: " + info.missing);
#ifdef ODELAB_ENGINE_BULLET
  if (name == "bullet") return makeBullet(setting);
#endif
#ifdef ODELAB_ENGINE_MUJOCO
  if (name == "mujoco") return makeMujoco(setting);
#endif
#if defined(ODELAB_ENGINE_NODE)
  if (isWasmEngine(name)) return makeNodeEngine(name, setting);
#elif defined(ODELAB_ENGINE_BROWSER)
  if (isWasmEngine(name)) return makeBrowserEngine(name, setting);
#endif
  (void)setting;
  throw world::EngineError("engine '" + name + "' is not one of " + engineList());
}

}  // namespace

world::EngineCatalog catalog() { return {&list, &make}; }

}  // namespace odelab::engines
