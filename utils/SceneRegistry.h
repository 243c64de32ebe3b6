#pragma once

#include <memory>
#include <string>
#include <vector>

#include "AbstractWindow.h"

namespace odelab {

// One scene of the library: its program's name, its --help description and
// a way to make it. Each scene file ends with ODELAB_SCENE(...); the
// registry lists them in the order of CMake's program list.
struct SceneEntry {
  const char* name;  // "test4", the program's name
  const char* description;
  std::unique_ptr<AbstractWindow> (*make)();
};

// Every scene, from CMake's one list (generated: SceneRegistry.cpp in the build).
const std::vector<SceneEntry>& sceneRegistry();
// The scene called `name`, or nullptr.
const SceneEntry* findScene(const std::string& name);
// The output files (names in --out-dir) of every scene, which a session
// that may switch to any scene keeps its other files off.
std::vector<std::string> outputFileNamesOfEveryScene();

}  // namespace odelab

// At the end of a scene's source: ODELAB_SCENE(test4, DifferentWeights, "A 5000 kg cube ...");
// defines odelab_scene_test4(), which the program and the registry call.
#define ODELAB_SCENE(NAME, CLASS, DESCRIPTION)                                                  \
  odelab::SceneEntry odelab_scene_##NAME() {                                                    \
    return {#NAME, DESCRIPTION,                                                                 \
            []() -> std::unique_ptr<odelab::AbstractWindow> { return std::make_unique<CLASS>(); }}; \
  }
