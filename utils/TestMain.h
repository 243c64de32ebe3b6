#pragma once

#include "AbstractWindow.h"
#include "SceneRegistry.h"

namespace odelab {

// Parses the command line (common options plus the scene's), initialises ODE
// with its handlers, and runs the scene headless or in a window. Returns the
// process exit status (utils/ExitCodes.h).
// The launcher's window goes from scene to scene (Page Down / Page Up)
// without leaving the window: next() makes the scene that follows the one
// just ended, with the same options. The last one on screen reports.
class SceneSwitching {
 public:
  virtual ~SceneSwitching() = default;
  // The scene `offset` places on from the one just ended (wrapping): Page
  // Down +1, Page Up -1, a click in the panel's scene list any.
  virtual AbstractWindow& next(int offset, const RunOptions& options) = 0;
  virtual std::vector<SceneChoice> scenes() const = 0;  // every scene, in order
  virtual int current() const = 0;                       // the index of the one on screen
  // The output file names of every scene it may switch to, which the
  // session's other files must not name.
  virtual std::vector<std::string> outputFileNames() const = 0;
};

// With `switching` (the launcher), a window run may go on to other scenes.
int runScene(AbstractWindow& scene, const char* description, int argc, char** argv,
             SceneSwitching* switching = nullptr);

// Every test's main(): `int main(int argc, char** argv) { return odelab::runTest<Test1>(argc, argv, "..."); }`
// Makes the registry's scene and runs it. A scene that declares a key twice
// fails here, at start-up: "error: scene declaration: ...", status 1.
int runEntry(const SceneEntry& entry, int argc, char** argv, SceneSwitching* switching = nullptr);

}  // namespace odelab
