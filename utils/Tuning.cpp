#include "Tuning.h"

#include <algorithm>

namespace odelab {

std::vector<const Knob*> Tuning::inReportOrder() const {
  std::vector<const Knob*> order;
  for (const Knob& knob : knobs_) order.push_back(&knob);
  std::stable_sort(order.begin(), order.end(), [](const Knob* a, const Knob* b) {
    if (a->appliesToWorld != b->appliesToWorld) return a->appliesToWorld;
    return a->appliesToWorld && a->reportRank < b->reportRank;
  });
  return order;
}

std::string Tuning::settingsInForce() const {
  std::string text;
  for (const Knob* knob : inReportOrder()) {
    if (knob->inMessage.empty()) continue;
    std::string words = knob->inMessage;
    words.replace(words.find('#'), 1, knob->words());
    text += (text.empty() ? " (" : ", ") + words;
  }
  return text + ")";
}

}  // namespace odelab
