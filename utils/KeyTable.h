#pragma once

#include <SDL2/SDL_keycode.h>

#include <functional>
#include <string>
#include <vector>

namespace odelab {

// One key of the scene: the same table drives dispatch, --help and doc/.
struct KeyBinding {
  SDL_Keycode key;
  std::string keyName;
  std::string description;
  std::function<void(int direction)> action;  // direction is -1 with Shift, else +1
  // Whether the key changes the simulation: such presses are recorded on the
  // timeline (rewind replays them) and in the run log. View keys are not.
  bool recorded = true;
  // A knob's key (and F2) writes the change it made to the run log itself,
  // in place of the key's description.
  bool logsItself = false;
};

class KeyTable {
 public:
  // A key bound twice is a mistake in the scene: std::logic_error, at start-up.
  void bind(KeyBinding binding);
  // Takes over a key bound already (a scene's R for the shared one);
  // std::logic_error when the key has no binding to take over.
  void replace(KeyBinding binding);
  const KeyBinding* find(SDL_Keycode key) const;
  const std::vector<KeyBinding>& bindings() const { return bindings_; }
  // "F3           ERP up by ..." for every binding, in order.
  std::vector<std::string> helpLines() const;

 private:
  std::vector<KeyBinding> bindings_;
};

}  // namespace odelab
