#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "AbstractWindow.h"
#include "SceneRegistry.h"

namespace odelab {

// Parses the command line (common options plus the scene's), initialises ODE
// with its handlers, and runs the scene headless or in a window. Returns the
// process exit status (utils/ExitCodes.h).
// The launcher's window goes from scene to scene (Page Down / Page Up)
// without leaving the window: next() makes the scene that follows the one
// just ended, with the same options. The runner ends, measures and destroys
// the scene it leaves (its files, locks and hooks let go: OpenScene.h)
// before it asks for the next. Each scene shown reports its own metrics
// (SceneVisits.h).
class SceneSwitching {
 public:
  virtual ~SceneSwitching() = default;
  // The scene `offset` places on from the one just ended (wrapping): Page
  // Down +1, Page Up -1, a click in the panel's scene list any, 0 the same
  // scene again. Made with `options`, its own settings at their defaults.
  virtual std::unique_ptr<AbstractWindow> next(int offset, const RunOptions& options) = 0;
  virtual std::vector<SceneChoice> scenes() const = 0;  // every scene, in order
  virtual int current() const = 0;                       // the index of the one on screen
  // After parsing, before any scene runs: the window's options hold for
  // every scene it may switch to (--seconds at least one step of each).
  // Throws UsageError naming the option and the scene.
  virtual void checkOptions(const RunOptions& options) const = 0;
  // The output file names of every scene it may switch to, which the
  // session's other files must not name.
  virtual std::vector<std::string> outputFileNames() const = 0;
};

// With `switching` (the launcher), a window run may go on to other scenes.
// `makeAnother` makes the same scene again, unparsed (another of `first`):
// --compare runs one on each engine named (utils/CompareRun.h); without it
// --compare is refused.
int runScene(std::unique_ptr<AbstractWindow> first, const char* description, int argc, char** argv,
             SceneSwitching* switching = nullptr,
             const std::function<std::unique_ptr<AbstractWindow>()>& makeAnother = {});

// Every test's main(): `int main(int argc, char** argv) { return odelab::runTest<Test1>(argc, argv, "..."); }`
// Makes the registry's scene and runs it. A scene that declares a key twice
// fails here, at start-up: "error: scene declaration: ...", status 1.
int runEntry(const SceneEntry& entry, int argc, char** argv, SceneSwitching* switching = nullptr);

}  // namespace odelab
