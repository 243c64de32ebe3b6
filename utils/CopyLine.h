#pragma once

#include <deque>
#include <string>
#include <vector>

namespace CLI {
class Option;
}

namespace odelab {

class AbstractWindow;
struct Knob;

// One option of a command line: "--erp" with "0.2", or a flag ("--ccd").
struct LineOption {
  std::string option, value;
  bool flag = false;
};

// The scene's own options (plain CLI11 options such as --ccd or --space,
// neither setting nor knob) that the command line gave, as it gave them:
// no panel row or key of the framework knows them, so the copied line
// repeats them.
std::vector<LineOption> givenOptions(const std::vector<const CLI::Option*>& sceneOptions);

// Every tunable value in force as the options that set it, in one list: each
// knob (world settings, contact choices, the scene's), --seed, then the
// scene's own options as given. A knob is
// left out only where naming it would change or refuse the run: its value is
// outside its range (a stand-in for the scene's own default, as test5's
// --plates 0), it is a default the scene picks (Knob::sceneDefault) and was
// neither given nor changed, or it needs a flag the line does not carry.
std::vector<LineOption> tuningOptions(const std::deque<Knob>& knobs, unsigned seed, const std::vector<LineOption>& given);

// "test4 --erp 0.2 ... --seed 1": words a POSIX shell passes on unchanged
// (anything else single-quoted), numbers in their shortest exact form.
std::string commandLineText(const std::string& program, const std::vector<LineOption>& options);

// The command line that starts `scene` again with everything it is tuned by
// now: the panel's "Copy as command line" and --print-command-line.
std::string copyLine(const AbstractWindow& scene);

}  // namespace odelab
