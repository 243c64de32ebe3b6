// odelab: every scene of the library from one program.
//   odelab [window options]             a window with test1 (Jumping Balls); Page Down / Page Up
//                                       or the panel's scene list switch scenes, H lists the keys
//   odelab --list                       the scenes, one a line: name, tab, description
//   odelab --scene NAME [options]       NAME as its own program runs it (same options,
//                                       headless too: the same metrics and state hash)
// The runner owns each scene the window opens and destroys it before the
// next is made (utils/OpenScene.h); this file only says which scene is next.
#include <algorithm>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "CommandLine.h"
#include "ExitCodes.h"
#include "FormatValue.h"
#include "SceneRegistry.h"
#include "SceneRunner.h"
#include "world/WorldFileScene.h"
#include "world/WorldJson.h"
#include "Adapters.h"

namespace {

constexpr const char* USAGE =
    "usage: odelab [window options]        (opens on test1; Page Down / Page Up or the panel's list switch scenes)\n"
    "       odelab --list\n"
    "       odelab --scene NAME [the options of NAME's program; odelab --scene NAME --help lists them]\n"
    "       odelab --world FILE [options]  a world file (doc/world-format.md; testN --export-world writes one),\n"
    "                                      or a MuJoCo MJCF model (FILE.xml) or an SDF world (FILE.sdf),\n"
    "                                      translated to one\n"
    "In the window, every scene shown reports in --metrics-json as visit<N>.<scene>.<metric> once the\n"
    "window has switched, --record numbers frames over the whole window, and --seconds must be at\n"
    "least one step of every scene.\n";

// Page Down / Page Up or the panel's scene list in the window: another scene
// of the registry, made fresh with the window's options (its knobs at their defaults).
class RegistrySwitching : public odelab::SceneSwitching {
 public:
  explicit RegistrySwitching(const odelab::SceneEntry& first) {
    const auto& scenes = odelab::sceneRegistry();
    while (index_ < scenes.size() && scenes[index_].make != first.make) ++index_;
  }

  // The runner has destroyed the scene that ended (OpenScene) before this call.
  std::unique_ptr<odelab::AbstractWindow> next(int offset, const odelab::RunOptions& options) override {
    const long count = static_cast<long>(odelab::sceneRegistry().size());
    index_ = static_cast<size_t>(((static_cast<long>(index_) + offset) % count + count) % count);
    std::unique_ptr<odelab::AbstractWindow> scene = odelab::sceneRegistry()[index_].make();
    scene->offerSceneSwitch(scenes(), current());
    scene->setRunOptions(options);
    return scene;
  }

  // A scene switched to runs at its own step: --seconds shorter than that
  // step would end it after one step it was not asked for.
  void checkOptions(const odelab::RunOptions& options) const override {
    for (const odelab::SceneEntry& entry : odelab::sceneRegistry()) {
      const double step = entry.make()->tuning().settings().step;
      if (options.seconds > 0 && options.seconds < step)
        throw odelab::UsageError("--seconds: " + odelab::formatValue(options.seconds) + " s is less than one step of " +
                                 entry.name + " (" + odelab::formatValue(step) +
                                 " s), a scene this window can switch to (Page Down / Page Up); give --seconds " +
                                 odelab::formatValue(step) + " or more, or run --headless");
    }
  }

  // The panel's list shows each scene as "test2  Pendulum", its description
  // as the tooltip: the name and title of its registration.
  std::vector<odelab::SceneChoice> scenes() const override {
    if (choices_.empty()) {
      size_t longest = 0;
      for (const odelab::SceneEntry& entry : odelab::sceneRegistry()) longest = std::max(longest, std::strlen(entry.name));
      // Names padded to one width, so the titles line up in the panel's font.
      for (const odelab::SceneEntry& entry : odelab::sceneRegistry()) {
        std::string name = entry.name;
        name.resize(longest + 2, ' ');
        choices_.push_back({name + entry.title, entry.description});
      }
    }
    return choices_;
  }

  int current() const override { return static_cast<int>(index_); }
  std::vector<std::string> outputFileNames() const override { return odelab::outputFileNamesOfEveryScene(); }

 private:
  size_t index_ = 0;
  mutable std::vector<odelab::SceneChoice> choices_;
};

// The window opens on test1, Jumping Balls: fifty balls fall and bounce from
// the first frame, each to its own height, so the lab's subject (how ODE
// keeps each restitution) is on screen before any key is pressed. test0's
// platform would wait for objects, and other scenes wait on a key or take
// seconds to show their point.
const odelab::SceneEntry& firstWindowScene() {
  const odelab::SceneEntry* scene = odelab::findScene("test1");
  return scene ? *scene : odelab::sceneRegistry().front();
}

int usageError(const std::string& message) {
  std::cerr << "error: " << message << '\n' << USAGE;
  return odelab::exit_code::USAGE;
}

// --world FILE: the file read and checked whole before anything runs.
// --compare makes the scene once more for each engine, from the world read here.
int runWorldFile(const std::string& path, std::vector<char*>& arguments) {
  std::shared_ptr<const odelab::world::World> world;
  try {
    world = std::make_shared<const odelab::world::World>(odelab::world::readWorldFile(path));
  } catch (const odelab::world::WorldFileError& error) {
    std::cerr << "error: --world: " << error.what() << '\n';
    return odelab::exit_code::USAGE;
  }
  // Said once, before any figure: what an imported file (MJCF) had that the world does not carry.
  for (const std::string& note : world->notes) std::cerr << "odelab: --world: note: " << note << '\n';
  const auto make = [world, path]() -> std::unique_ptr<odelab::AbstractWindow> {
    auto scene = std::make_unique<odelab::world::WorldFileScene>(*world);
    scene->identify("world", scene->fileTitle(path));
    scene->readsFile("--world", path);
    return scene;
  };
  return odelab::runScene(make(), "A world file (doc/world-format.md) run in ODE or, with --engine, another engine.",
                          static_cast<int>(arguments.size()), arguments.data(), nullptr, make);
}

}  // namespace

int main(int argc, char** argv) {
  // The engines other than ODE that --engine may name (peers/engines).
  odelab::world::installEngineCatalog(odelab::engines::catalog());
  const std::string first = argc > 1 ? argv[1] : "";
  if (first == "--help" || first == "-h") {
    std::cout << USAGE;
    return odelab::exit_code::OK;
  }
  if (first == "--list" && argc == 2) {
    for (const odelab::SceneEntry& scene : odelab::sceneRegistry())
      std::cout << scene.name << '\t' << scene.description << '\n';
    return odelab::exit_code::OK;
  }
  // --scene NAME or --scene=NAME anywhere, or --world FILE; every other argument is the scene's.
  std::string name, worldFile;
  bool named = false, worldGiven = false;
  std::vector<char*> arguments{argv[0]};  // the scene's program sees its own arguments only
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument.rfind("--scene=", 0) == 0 || (argument == "--scene" && i + 1 < argc)) {
      if (named) return usageError("--scene: given twice");
      named = true;
      name = argument == "--scene" ? argv[++i] : argument.substr(std::strlen("--scene="));
    } else if (argument.rfind("--world=", 0) == 0 || (argument == "--world" && i + 1 < argc)) {
      if (worldGiven) return usageError("--world: given twice");
      worldGiven = true;
      worldFile = argument == "--world" ? argv[++i] : argument.substr(std::strlen("--world="));
    } else {
      arguments.push_back(argv[i]);
    }
  }
  if (worldGiven) {
    if (named) return usageError("--world: a world file is the scene; leave out --scene");
    return runWorldFile(worldFile, arguments);
  }
  // No --scene: the window starts with a scene in motion (firstWindowScene).
  const odelab::SceneEntry* scene = named ? odelab::findScene(name) : &firstWindowScene();
  if (!scene) return usageError("--scene: no scene '" + name + "'; odelab --list names them");
  // The window switches scenes (Page Down / Page Up); a headless run is one scene's.
  bool headless = false;
  for (const char* argument : arguments) headless = headless || std::strcmp(argument, "--headless") == 0;
  if (headless && !named) return usageError("--headless: needs --scene NAME");
  RegistrySwitching switching(*scene);
  return odelab::runEntry(*scene, static_cast<int>(arguments.size()), arguments.data(),
                          headless ? nullptr : &switching);
}
