// The main() of every test program: it runs the one scene CMake names in
// ODELAB_SCENE_ENTRY (odelab_scene_test4 for test4), so the program links
// that scene alone.
#include "Adapters.h"
#include "SceneRunner.h"

odelab::SceneEntry ODELAB_SCENE_ENTRY();

int main(int argc, char** argv) {
  // The engines other than ODE that --engine may name (peers/engines).
  odelab::world::installEngineCatalog(odelab::engines::catalog());
  return odelab::runEntry(ODELAB_SCENE_ENTRY(), argc, argv);
}
