// odelab: every scene of the library from one program.
//   odelab --list                       the scenes, one a line: name, tab, description
//   odelab --scene NAME [options]       NAME as its own program runs it (same options,
//                                       headless too: the same metrics and state hash)
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "ExitCodes.h"
#include "SceneRegistry.h"
#include "TestMain.h"

namespace {

constexpr const char* USAGE =
    "usage: odelab --list\n"
    "       odelab --scene NAME [the options of NAME's program; odelab --scene NAME --help lists them]\n";

int usageError(const std::string& message) {
  std::cerr << "error: " << message << '\n' << USAGE;
  return odelab::exit_code::USAGE;
}

}  // namespace

int main(int argc, char** argv) {
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
  // --scene NAME or --scene=NAME anywhere; every other argument is the scene's.
  std::string name;
  bool named = false;
  std::vector<char*> arguments{argv[0]};  // the scene's program sees its own arguments only
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument.rfind("--scene=", 0) == 0 || (argument == "--scene" && i + 1 < argc)) {
      if (named) return usageError("--scene: given twice");
      named = true;
      name = argument == "--scene" ? argv[++i] : argument.substr(std::strlen("--scene="));
    } else {
      arguments.push_back(argv[i]);
    }
  }
  if (!named) return usageError(first.empty() ? "--scene: no scene given" : "--scene NAME (or --list) is needed");
  const odelab::SceneEntry* scene = odelab::findScene(name);
  if (!scene) return usageError("--scene: no scene '" + name + "'; odelab --list names them");
  return odelab::runEntry(*scene, static_cast<int>(arguments.size()), arguments.data());
}
