#include "SceneKeys.h"

namespace odelab {

std::vector<const KeyBinding*> sceneKeys(const KeyTable& keys) {
  std::vector<const KeyBinding*> own;
  for (const KeyBinding& binding : keys.bindings()) {
    const bool sceneOnly = binding.key == SDLK_b || binding.key == SDLK_n || binding.key == SDLK_q ||
                           binding.key == SDLK_t || binding.key == SDLK_F5;
    const bool ownReset = binding.key == SDLK_r && binding.description.rfind("reset the scene", 0) != 0;
    if (sceneOnly || ownReset) own.push_back(&binding);
  }
  return own;
}

std::string shortKeyText(const KeyBinding& binding) {
  std::string text = binding.description;
  for (const char* end : {" (", ";", ":"}) {
    const size_t at = text.find(end);
    if (at != std::string::npos) text.erase(at);
  }
  return binding.keyName + " " + text;
}

}  // namespace odelab
