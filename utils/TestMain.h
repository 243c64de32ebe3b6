#pragma once

#include "AbstractWindow.h"
#include "SceneRegistry.h"

namespace odelab {

// Parses the command line (common options plus the scene's), initialises ODE
// with its handlers, and runs the scene headless or in a window. Returns the
// process exit status (utils/ExitCodes.h).
int runScene(AbstractWindow& scene, const char* description, int argc, char** argv);

// Every test's main(): `int main(int argc, char** argv) { return odelab::runTest<Test1>(argc, argv, "..."); }`
// Makes the registry's scene and runs it. A scene that declares a key twice
// fails here, at start-up: "error: scene declaration: ...", status 1.
int runEntry(const SceneEntry& entry, int argc, char** argv);

}  // namespace odelab
