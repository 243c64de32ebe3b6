// Prints the lines a scene's window HUD shows, compact (the default), after
// SECONDS of simulated time, one a line, without opening a window:
//   compact_hud SCENE SECONDS
// The front end draws exactly these (AbstractWindow::hudLines), so a check
// can hold the compact HUD to what it must say.
#include <ode/ode.h>

#include <iostream>
#include <string>

#include "RunOptions.h"
#include "check_cli.h"
#include "SceneRegistry.h"

int main(int argc, char** argv) {
  std::string name;
  double seconds = 0;
  CLI::App app{"Prints the lines a scene's window HUD shows (compact) after SECONDS of simulated time, without a "
               "window.",
               "compact_hud"};
  app.add_option("scene", name, "the scene, as its program is named (test0 ...)")->required();
  app.add_option("seconds", seconds, "simulated seconds to step first")->required()->check(CLI::Range(0.0, 1e6));
  if (auto status = checks::parse(app, argc, argv)) return *status;
  const odelab::SceneEntry* entry = odelab::findScene(name);
  if (!entry) {
    std::cerr << "compact_hud: error: no scene '" << name << "'\n";
    return 2;
  }
  dInitODE2(0);
  {
    std::unique_ptr<odelab::AbstractWindow> scene = entry->make();
    odelab::RunOptions options;
    options.headless = true;  // no window: nothing here may wait for one
    scene->initialize(options);
    while (scene->run().simulatedTime() < seconds)
      if (!scene->stepOnce()) break;
    for (const std::string& line : scene->hudLines()) std::cout << line << '\n';
    scene->shutdown();
  }
  dCloseODE();
  return 0;
}
