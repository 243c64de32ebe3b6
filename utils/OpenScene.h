#pragma once

#include <memory>
#include <string>

#include "AbstractWindow.h"

namespace odelab {

// The scene a run has open, and everything it holds while open: its world,
// its output files with their locks (Test2_output.txt: the scene's own
// members), the exit hook that marks those files when a library calls
// exit() inside the run (Xlib's, when the display goes away), and ODE's
// error context (OdeMessages::setRunContext), which names the scene's moment
// and ends its files on a pool thread's error. odelab's window switches
// scenes: it closes one before the next is made, so the next may open the
// same files, and every hook names the scene on screen. close() is the one
// place all of it is let go.
class OpenScene {
 public:
  explicit OpenScene(std::unique_ptr<AbstractWindow> scene) : scene_(std::move(scene)) {}
  ~OpenScene() { close(); }
  OpenScene(const OpenScene&) = delete;
  OpenScene& operator=(const OpenScene&) = delete;

  bool isOpen() const { return scene_ != nullptr; }
  AbstractWindow& scene() { return *scene_; }
  // Points the exit hook and ODE's error context at this scene: once ODE
  // is initialised, before the scene's first step.
  void hook();
  // Lets go, in this order: the hooks, the world (shutdown, while ODE is
  // still initialised), then the scene itself, whose destruction closes its
  // files and their locks. Does nothing when closed already.
  void close();
  // Takes `next` after close(); hooked when this one was.
  void open(std::unique_ptr<AbstractWindow> next);

 private:
  std::unique_ptr<AbstractWindow> scene_;
  bool hooked_ = false;
};

// The scene's output files end with "# incomplete: ...; why" (once: a file
// ended already keeps its line). A failure to write it is printed.
void markCutShort(AbstractWindow& scene, const std::string& why);

}  // namespace odelab
