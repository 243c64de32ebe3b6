// odelab_engine_step: one engine, one world file, no scene: builds the world,
// steps it, and prints every body's state as JSON lines. It is how the
// engine checks (checks/engines.cmake) assert physical facts of an adapter
// alone, and how an adapter is tried by hand:
//   odelab_engine_step --engine bullet --world ball.json --seconds 2 --every 100
// Each line: {"step": N, "time": t, "bodies": [[px,py,pz, qw,qx,qy,qz, vx,vy,vz, wx,wy,wz, enabled], ...]}
// and a last line {"notes": [...], "engine_wall_s": ..., "engine_cpu_s": ...}.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <string>

#include "Adapters.h"
#include "world/WorldJson.h"

namespace {

nlohmann::json statesOf(const odelab::world::Engine& engine, const odelab::world::World& world) {
  nlohmann::json bodies = nlohmann::json::array();
  for (size_t i = 0; i < world.bodies.size(); ++i) {
    const odelab::world::BodyState s = engine.state(static_cast<int>(i));
    bodies.push_back({s.position[0], s.position[1], s.position[2], s.orientation[0], s.orientation[1], s.orientation[2],
                      s.orientation[3], s.linearVelocity[0], s.linearVelocity[1], s.linearVelocity[2],
                      s.angularVelocity[0], s.angularVelocity[1], s.angularVelocity[2], s.enabled ? 1 : 0});
  }
  return bodies;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"One engine steps one world file and prints every body's state (doc/world-format.md)",
               "odelab_engine_step"};
  std::string engineName, worldPath;
  double seconds = 1.0;
  long long every = 1;
  bool best = false;
  app.add_option("--engine", engineName, "bullet, mujoco, havok, jolt, rapier or physx")->required();
  app.add_option("--world", worldPath, "the world file")->required();
  app.add_option("--seconds", seconds, "simulated seconds")->check(CLI::Range(0.0, 1e6));
  app.add_option("--every", every, "print every N steps (and the last)")->check(CLI::Range(1LL, 1000000000LL));
  app.add_flag("--best", best, "the engine's best settings for accuracy, not its defaults");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  }
  odelab::world::installEngineCatalog(odelab::engines::catalog());
  try {
    const odelab::world::World world = odelab::world::readWorldFile(worldPath);
    auto engine = odelab::world::makeEngine(
        engineName, best ? odelab::world::EngineSetting::Best : odelab::world::EngineSetting::Default);
    engine->build(world);
    const long long steps = std::llround(seconds / world.settings.step);
    std::cout.precision(17);
    for (long long n = 0; n <= steps; ++n) {
      if (n > 0) engine->step();
      if (n % every == 0 || n == steps)
        std::cout << nlohmann::json{{"step", n}, {"time", n * world.settings.step}, {"bodies", statesOf(*engine, world)}}.dump()
                  << "\n";
    }
    std::cout << nlohmann::json{{"notes", engine->translationNotes()},
                                {"engine_wall_s", engine->engineWallSeconds()},
                                {"engine_cpu_s", engine->engineCpuSeconds()}}
                     .dump()
              << "\n";
  } catch (const odelab::world::WorldFileError& error) {
    std::cerr << "odelab_engine_step: error: " << error.what() << "\n";
    return 2;
  } catch (const odelab::world::EngineError& error) {
    std::cerr << "odelab_engine_step: " << engineName << ": " << error.what() << "\n";
    return 4;
  }
  return 0;
}
