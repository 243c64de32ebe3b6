#include "OpenScene.h"

#include <cstdlib>
#include <exception>
#include <iostream>

#include "OdeMessages.h"

namespace odelab {

namespace {

// The scene the exit hook marks: the hooked one, or none.
AbstractWindow* hookedScene = nullptr;

void markOutputsAtExit() {
  AbstractWindow* scene = hookedScene;
  hookedScene = nullptr;
  if (scene) markCutShort(*scene, "the program exited inside the run (exit() from a library; see standard error)");
}

}  // namespace

void markCutShort(AbstractWindow& scene, const std::string& why) {
  try {
    scene.endOutputs(why);
  } catch (const std::exception& error) {  // a full disk: the file stays without a last line
    std::cerr << "error: " << error.what() << '\n';
  }
}

void OpenScene::hook() {
  static const bool registered = std::atexit(markOutputsAtExit) == 0;
  (void)registered;
  AbstractWindow* scene = scene_.get();
  hookedScene = scene;
  OdeMessages::setRunContext([scene] { return scene->momentAndSettings(); },
                             [scene](const std::string& why) { scene->endOutputs(why); });
  hooked_ = true;
}

void OpenScene::close() {
  if (!scene_) return;
  if (hooked_) {
    if (hookedScene == scene_.get()) hookedScene = nullptr;
    OdeMessages::setRunContext({}, {});
  }
  scene_->shutdown();
  scene_.reset();
}

void OpenScene::open(std::unique_ptr<AbstractWindow> next) {
  close();
  scene_ = std::move(next);
  if (hooked_) hook();
}

}  // namespace odelab
