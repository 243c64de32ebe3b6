// Prints the lines a scene's window HUD shows, compact (the default), after
// SECONDS of simulated time, one a line, without opening a window:
//   compact_hud SCENE SECONDS
// The front end draws exactly these (AbstractWindow::hudLines), so a check
// can hold the compact HUD to what it must say.
#include <ode/ode.h>

#include <cstdlib>
#include <iostream>

#include "RunOptions.h"
#include "SceneRegistry.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: compact_hud SCENE SECONDS\n";
    return 2;
  }
  const odelab::SceneEntry* entry = odelab::findScene(argv[1]);
  if (!entry) {
    std::cerr << "compact_hud: no scene '" << argv[1] << "'\n";
    return 2;
  }
  dInitODE2(0);
  {
    std::unique_ptr<odelab::AbstractWindow> scene = entry->make();
    odelab::RunOptions options;
    options.headless = true;  // no window: nothing here may wait for one
    scene->initialize(options);
    const double seconds = std::atof(argv[2]);
    while (scene->run().simulatedTime() < seconds)
      if (!scene->stepOnce()) break;
    for (const std::string& line : scene->hudLines()) std::cout << line << '\n';
    scene->shutdown();
  }
  dCloseODE();
  return 0;
}
