#include "SceneVisits.h"

namespace odelab {

void addPrefixed(Metrics& into, const std::string& prefix, const Metrics& from) {
  for (const auto& entry : from.entries()) into.setAs(prefix + entry.first, from, entry.first);
  for (const auto& [name, texts] : from.texts()) into.setTexts(prefix + name, texts);
}

void SceneVisits::add(const std::string& scene, const Metrics& metrics) { visits_.push_back({scene, metrics}); }

Metrics SceneVisits::session(const std::string& scene, const Metrics& last) const {
  if (visits_.empty()) return last;
  Metrics all;
  all.set("visits", static_cast<double>(visits_.size() + 1));
  const auto addVisit = [&all](size_t number, const std::string& name, const Metrics& metrics) {
    addPrefixed(all, "visit" + std::to_string(number) + "." + name + ".", metrics);
  };
  for (size_t i = 0; i < visits_.size(); ++i) addVisit(i + 1, visits_[i].scene, visits_[i].metrics);
  addVisit(visits_.size() + 1, scene, last);
  return all;
}

}  // namespace odelab
