#include "KeyTable.h"

#include <algorithm>
#include <stdexcept>

namespace odelab {

void KeyTable::bind(KeyBinding binding) {
  if (const KeyBinding* earlier = find(binding.key))
    throw std::logic_error("key " + binding.keyName + " is bound twice: \"" + earlier->description + "\" and \"" +
                           binding.description + "\"");
  bindings_.push_back(std::move(binding));
}

void KeyTable::replace(KeyBinding binding) {
  const SDL_Keycode key = binding.key;
  const auto earlier =
      std::find_if(bindings_.begin(), bindings_.end(), [key](const KeyBinding& b) { return b.key == key; });
  if (earlier == bindings_.end()) throw std::logic_error("key " + binding.keyName + ": nothing bound to replace");
  bindings_.erase(earlier);
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
