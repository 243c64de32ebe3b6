#pragma once

#include <memory>
#include <string>
#include <vector>

#include "AbstractWindow.h"

namespace odelab {

// One scene of the library: its program's name and title (its line of
// tests/scenes/scenes.txt), its --help description and a way to make it.
// Each scene file ends with ODELAB_SCENE(...); the registry lists them in
// the list's order.
struct SceneEntry {
  const char* name;   // "test4", the program's name
  const char* title;  // "Different Weights"
  const char* description;
  std::unique_ptr<AbstractWindow> (*make)();  // the scene, named and titled as above
};

// Every scene, from CMake's one list (generated: SceneRegistry.cpp in the build).
const std::vector<SceneEntry>& sceneRegistry();
// The scene called `name`, or nullptr.
const SceneEntry* findScene(const std::string& name);
// The output files (names in --out-dir) of every scene, which a session
// that may switch to any scene keeps its other files off.
std::vector<std::string> outputFileNamesOfEveryScene();

}  // namespace odelab

// At the end of a scene's source: ODELAB_SCENE(DifferentWeights, "A 5000 kg cube ...");
// defines odelab_scene_test4(), which the program and the registry call.
// The name and the title are not in the source: the build compiles it with
// ODELAB_SCENE_NAME (test4) and ODELAB_SCENE_TITLE ("Different Weights")
// from its line of tests/scenes/scenes.txt, so a copy of a scene's file,
// listed on a line of its own, is a new scene.
#if defined(ODELAB_SCENE_NAME) && defined(ODELAB_SCENE_TITLE)
#define ODELAB_SCENE_JOIN_(A, B) A##B
#define ODELAB_SCENE_JOIN(A, B) ODELAB_SCENE_JOIN_(A, B)
#define ODELAB_SCENE_TEXT_(A) #A
#define ODELAB_SCENE_TEXT(A) ODELAB_SCENE_TEXT_(A)
#define ODELAB_SCENE(CLASS, DESCRIPTION)                                                         \
  odelab::SceneEntry ODELAB_SCENE_JOIN(odelab_scene_, ODELAB_SCENE_NAME)() {                     \
    return {ODELAB_SCENE_TEXT(ODELAB_SCENE_NAME), ODELAB_SCENE_TITLE, DESCRIPTION,                \
            []() -> std::unique_ptr<odelab::AbstractWindow> {                                     \
              auto scene = std::make_unique<CLASS>();                                             \
              scene->identify(ODELAB_SCENE_TEXT(ODELAB_SCENE_NAME), ODELAB_SCENE_TITLE);          \
              return scene;                                                                       \
            }};                                                                                   \
  }
#else
#define ODELAB_SCENE(CLASS, DESCRIPTION) \
  static_assert(false, "a scene is compiled with its name and title from tests/scenes/scenes.txt")
#endif
