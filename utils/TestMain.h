#pragma once

#include <memory>
#include <stdexcept>

#include "AbstractWindow.h"

namespace odelab {

// Parses the command line (common options plus the scene's), initialises ODE
// with its handlers, and runs the scene headless or in a window. Returns the
// process exit status (utils/ExitCodes.h).
int runScene(AbstractWindow& scene, const char* description, int argc, char** argv);
// Prints "error: scene declaration: ..." and returns exit_code::RUNTIME_ERROR.
int reportBrokenScene(const std::logic_error& error);

// Every test's main(): `int main(int argc, char** argv) { return odelab::runTest<Test1>(argc, argv, "..."); }`
// A scene that declares a key twice (or a knob wrongly) fails here, at
// start-up, with the reason on stderr.
template <class Scene>
int runTest(int argc, char** argv, const char* description) {
  std::unique_ptr<Scene> scene;
  try {
    scene = std::make_unique<Scene>();
  } catch (const std::logic_error& error) {
    return reportBrokenScene(error);
  }
  return runScene(*scene, description, argc, argv);
}

}  // namespace odelab
