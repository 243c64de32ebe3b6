// The command line and run loop shared by the peer programs (bullet_lab,
// mujoco_lab): the same options and metric names as the ODE programs'
// headless runs, so the lab runs either the same way.
#include <sys/resource.h>

#include <chrono>
#include <iostream>
#include <map>

#include "CommandLine.h"
#include "Measurements.h"
#include "Metrics.h"
#include "PeerScene.h"
#include "SafeFile.h"
#include "shared/SceneConstants.h"

namespace odelab::peers {

namespace {

using Measurement = Tally (*)(Engine&, const RunOptions&, Metrics&);

const std::map<std::string, Measurement> MEASUREMENTS = {
    {"test2", measureEnergy}, {"test4", measureHold},  {"test8", measureElongation},
    {"test9", measureBounces}, {"test10", measureWall},
    {"test7", measureJoints},   {"test1", measureRebounds}, {"test6", measureUpright},
    {"test3", measureChain},    {"test5", measurePlates},
};

double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

}  // namespace

int runPeer(int argc, char** argv, Engine& engine) {
  CLI::App app{"The thesis's measurement scenes on " + engine.name() +
               ", headless, with the ODE programs' metric names (doc/peers.md)."};
  RunOptions options;
  std::string setting = "default", metricsJson, modelFile;
  bool headless = false;
  std::vector<std::string> scenes;
  for (const auto& entry : MEASUREMENTS) scenes.push_back(entry.first);
  app.add_option("--scene", options.scene, "the scene, named as the ODE program that measures it")
      ->check(CLI::IsMember(scenes))
      ->capture_default_str();
  // Every number finite and within its range, every value non-empty,
  // every count decimal: the ODE programs' rules, from utils/CommandLine.
  app.add_option("--step", options.step, "simulation step in s (test3: 0.005, its ODE program's, unless given)")->check(cli::finiteRange(1e-7, 0.1))->capture_default_str();
  app.add_option("--seconds", options.seconds, "simulated seconds (default: the ODE program's run for the scene)")
      ->check(cli::positive(86400.0));
  app.add_option("--setting", setting,
                 "default: the engine as a user gets it; best: the engine's most accurate settings for the scene")
      ->check(CLI::IsMember({"default", "best"}))
      ->capture_default_str();
  app.add_flag("--ccd", options.ccd, "test10: the engine's continuous collision detection (Bullet only)");
  app.add_option("--velocity", options.velocity, "test10: launch velocity in m/s")
      ->check(cli::finiteRange(1e-3, 1e7))
      ->capture_default_str();
  app.add_flag("--find-max-velocity", options.findMaxVelocity,
               "test10: scan from 1 m/s (every 1 m/s to 1000, every 0.1% above) for the highest velocity with every "
               "launch up to it stopped");
  app.add_option("--big-mass", options.bigMass, "test4: mass of the big cube in kg (default: the scene's)")
      ->check(cli::finiteRange(1e-3, 1e9));
  app.add_option("--bob-mass", options.bobMass, "test8: mass of the bob in kg (default: the scene's)")
      ->check(cli::finiteRange(1e-3, 1e9));
  app.add_option("--plates", options.plates, "test5: plates dropped (default: the scene's)")
      ->check(cli::integerRange(1, 100000));
  app.add_option("--spawn-interval", options.spawnInterval, "test5: simulated seconds between plates (default: the scene's)")
      ->check(cli::finiteRange(1e-6, 1e4));
  app.add_option("--metrics-json", metricsJson, "write the metrics to this file as JSON");
  app.add_option("--write-model", modelFile,
                 "write the scene's model as the engine reads it (MuJoCo: MJCF, test2 and test9) to this file and exit");
  app.set_version_flag("--version", engine.name() + " " + engine.version(), "print the engine and its version, and exit");
  app.add_flag("--headless", headless, "accepted for the lab's sake; the peers never open a window");
  cli::rejectEmptyValues(app);
  const std::optional<int> refused = cli::parseCommandLine(app, argc, argv, [&] {
    if (options.ccd && !engine.hasContinuousCollision())
      throw UsageError("--ccd: " + engine.name() + " has no continuous collision detection");
    if (options.ccd && options.scene != "test10") throw UsageError("--ccd: only test10 uses it");
    // test3 runs at its own step (the ODE program's) unless one is given.
    if (options.scene == "test3" && app.count("--step") == 0) options.step = scene::test3::SCENE_STEP;
    cli::refuseRunShorterThanStep(options.seconds, options.step);
    cli::requireReplaceableFile("--metrics-json", metricsJson);
    cli::requireReplaceableFile("--write-model", modelFile);
  });
  if (refused) return *refused;
  options.setting = setting == "best" ? Setting::Best : Setting::Default;
  if (!modelFile.empty()) {
    const std::string model = engine.modelText(options);
    if (model.empty()) {
      std::cerr << "error: --write-model: " << engine.name() << " has no model file for " << options.scene << '\n'
                << "Run with --help for the options.\n";
      return 2;
    }
    // Replaced whole, as every file the project writes (SafeFile.h).
    try {
      writeFileAtomically(modelFile, model);
    } catch (const std::exception& error) {
      std::cerr << "error: --write-model: " << error.what() << '\n';
      return 1;
    }
    return 0;
  }

  Metrics metrics;
  const double cpuBefore = processCpuSeconds();
  const auto wallBefore = std::chrono::steady_clock::now();
  const Tally tally = MEASUREMENTS.at(options.scene)(engine, options, metrics);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallBefore).count();
  const double cpu = processCpuSeconds() - cpuBefore;

  Metrics all;  // the run's own figures first, as the ODE programs write them
  all.set("steps", static_cast<double>(tally.steps));
  all.set("sim_seconds", tally.simSeconds);
  all.set("wall_seconds", wall);
  all.set("cpu_seconds", cpu);
  all.set("non_finite", tally.finite ? 0 : 1);
  for (const auto& [name, value] : metrics.entries()) all.set(name, value);
  std::cout << engine.name() << " " << options.scene << ", step " << options.step << " s, setting " << setting
            << (options.ccd ? " + ccd" : "") << ": " << engine.settingText(options) << '\n';
  all.print(std::cout);
  if (!metricsJson.empty()) {
    try {
      all.writeJsonAtomically(metricsJson);
    } catch (const std::exception& error) {
      std::cerr << "error: " << error.what() << '\n';
      return 1;
    }
  }
  return tally.finite ? 0 : 3;
}

}  // namespace odelab::peers
