#include "KnobReach.h"

namespace odelab {

namespace {

struct Reach {
  const char* knob;
  const char* words[2];  // a translation note naming one of them is about this knob
  bool odeOnly;          // true: never reaches another engine
};

const Reach REACHES[] = {
    {"erp", {"ERP", nullptr}, false},         {"cfm", {"CFM", nullptr}, false},
    {"iterations", {"iteration", nullptr}, false}, {"sor", {"SOR", "over-relaxation"}, true},
    {"solver", {"dWorldStep", "solver"}, true},
};

}  // namespace

std::string knobNotReached(const std::string& knobName, const std::string& engine,
                           const std::vector<std::string>& translationNotes) {
  if (engine.empty() || engine == "ode") return {};
  for (const Reach& reach : REACHES) {
    if (knobName != reach.knob) continue;
    for (const std::string& note : translationNotes)
      for (const char* word : reach.words)
        if (word && note.find(word) != std::string::npos) return engine + ": " + note;
    if (reach.odeOnly)
      return engine + " solves its own way: ODE's " + (knobName == "sor" ? "SOR over-relaxation" : "choice of solver") +
             " does not reach it";
    return {};
  }
  return {};
}

}  // namespace odelab
