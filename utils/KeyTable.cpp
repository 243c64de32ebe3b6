#include "KeyTable.h"

#include <algorithm>

namespace odelab {

void KeyTable::bind(KeyBinding binding) {
  const SDL_Keycode key = binding.key;
  bindings_.erase(std::remove_if(bindings_.begin(), bindings_.end(), [key](const KeyBinding& b) { return b.key == key; }),
                  bindings_.end());
  bindings_.push_back(std::move(binding));
}

const KeyBinding* KeyTable::find(SDL_Keycode key) const {
  for (const KeyBinding& binding : bindings_)
    if (binding.key == key) return &binding;
  return nullptr;
}

std::vector<std::string> KeyTable::helpLines() const {
  std::vector<std::string> lines;
  for (const KeyBinding& binding : bindings_) {
    std::string name = binding.keyName;
    name.resize(std::max<size_t>(name.size(), 12), ' ');
    lines.push_back(name + " " + binding.description);
  }
  return lines;
}

}  // namespace odelab
