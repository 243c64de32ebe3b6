#pragma once

#include "AbstractWindow.h"

namespace odelab {

// Parses the command line (common options plus the scene's), initialises ODE
// with its handlers, and runs the scene headless or in a window. Returns the
// process exit status (utils/ExitCodes.h).
int runScene(AbstractWindow& scene, const char* description, int argc, char** argv);

// Every test's main(): `int main(int argc, char** argv) { return odelab::runTest<Test1>(argc, argv, "..."); }`
template <class Scene>
int runTest(int argc, char** argv, const char* description) {
  Scene scene;
  return runScene(scene, description, argc, argv);
}

}  // namespace odelab
