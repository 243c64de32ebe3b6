#include "CopyLine.h"

#include <CLI/CLI.hpp>

#include "AbstractWindow.h"
#include "Knob.h"

namespace odelab {

namespace {

std::string longName(const CLI::Option& option) {
  const std::vector<std::string>& names = option.get_lnames();
  return names.empty() ? option.get_name() : "--" + names.front();
}

bool givenFlag(const std::vector<LineOption>& given, const std::string& flag) {
  for (const LineOption& option : given)
    if (option.option == flag) return true;
  return false;
}

// Whether the line carries `flag`: given as the scene's own option, or a switch knob's that is on.
bool carries(const std::string& flag, const std::deque<Knob>& knobs, const std::vector<LineOption>& given) {
  for (const Knob& knob : knobs)
    if (knob.kind == KnobKind::Switch && knob.option == flag && knob.get() > 0) return true;
  return givenFlag(given, flag);
}

// Whether naming the knob on a command line starts the run it is in now.
bool named(const Knob& knob, const std::deque<Knob>& knobs, const std::vector<LineOption>& given) {
  if (!knob.companion.empty() && !carries(knob.companion, knobs, given)) return false;
  if (knob.kind == KnobKind::Switch) return knob.get() > 0;  // a flag names only "on"
  if (!knob.accepts(knob.get())) return false;
  const bool given_ = knob.parsed && knob.parsed->count() > 0;
  return !knob.sceneDefault || given_ || knob.get() != knob.initial;
}

std::string shellWord(const std::string& text) {
  const bool plain = !text.empty() && text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                             "0123456789_.,:/+=-") == std::string::npos;
  if (plain) return text;
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

std::vector<LineOption> givenOptions(const std::vector<const CLI::Option*>& sceneOptions) {
  std::vector<LineOption> given;
  for (const CLI::Option* option : sceneOptions) {
    if (option->count() == 0) continue;
    if (option->get_expected_max() == 0) {  // a flag: CLI11 expects no value after it
      if (option->as<bool>()) given.push_back({longName(*option), "", true});  // "--ccd=false" is no flag
    } else {
      given.push_back({longName(*option), option->results().back()});  // the last one given counts
    }
  }
  return given;
}

std::vector<LineOption> tuningOptions(const std::deque<Knob>& knobs, unsigned seed, const std::vector<LineOption>& given) {
  std::vector<LineOption> line;
  for (const Knob& knob : knobs)
    if (!knob.option.empty() && named(knob, knobs, given))
      line.push_back(knob.kind == KnobKind::Switch ? LineOption{knob.option, "", true}
                                                   : LineOption{knob.option, knob.optionText()});
  line.push_back({"--seed", std::to_string(seed)});
  line.insert(line.end(), given.begin(), given.end());
  return line;
}

std::string commandLineText(const std::string& program, const std::vector<LineOption>& options) {
  std::string text = shellWord(program);
  for (const LineOption& option : options) {
    text += ' ' + option.option;
    if (!option.flag) text += ' ' + shellWord(option.value);
  }
  return text;
}

std::string copyLine(const AbstractWindow& scene) {
  return commandLineText(scene.programName(), tuningOptions(scene.tuning().knobs(), scene.options().seed,
                                                            scene.session().givenSceneOptions()));
}

}  // namespace odelab
