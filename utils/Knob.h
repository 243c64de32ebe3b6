#pragma once

#include <SDL2/SDL_keycode.h>

#include <functional>
#include <string>
#include <vector>

namespace CLI {
class Option;
}

namespace odelab {

// What a knob's number is: any value in its range, a whole number, or a
// span of simulated time that has to hold at least one step (a row, a
// spawn, a throw per step at most).
enum class KnobKind { Real, Integer, Interval };

// One scene value a person tunes, declared once: the command line, the
// F-key, the control panel, the HUD, the run log, rewind and
// --list-settings all read this declaration, so its range is one range.
// Scenes declare knobs in their constructor with AbstractWindow::declare().
struct Knob {
  std::string name;   // in --list-settings: "big_mass"
  std::string label;  // on the panel, the HUD and in change messages: "big cube mass"
  std::string unit;   // "kg", "" for none
  double* value = nullptr;  // Real and Interval knobs
  int* count = nullptr;     // Integer knobs
  double min = 0, max = 0;  // max is infinity where the option takes "inf" (mu)
  double sliderMax = 0;     // the panel slider's top where max is infinity
  KnobKind kind = KnobKind::Real;
  bool offAtZero = false;  // 0 is accepted too, below min, and means "off"
  std::string option;      // "--big-mass"; "" when only the panel sets it
  // The option is added by its owner (ContactChoices: --mu reads "inf"), not
  // from this declaration; the knob still names it, so that --list-settings does.
  bool ownParser = false;
  std::string help;        // --help's line
  SDL_Keycode key = SDLK_UNKNOWN;  // steps the value (Shift: back)
  std::string keyName, keyHelp;
  std::vector<double> ladder;  // the key's values, ascending; empty: the key's own stepper
  std::function<double(double current, int direction)> stepper;
  bool logScale = false;  // the panel's slider spans decades
  bool rebuilds = false;  // a new value starts a new run (the scene is built again)
  bool headlessOnly = false;  // only a headless run reads it (throws, launches)
  // Its declared value stands for a default the scene picks itself (headless
  // or window, scanning or not): the copied command line names it only once
  // it is given or changed, so that the line leaves that choice to the scene.
  bool sceneDefault = false;
  double initial = 0;  // the value it was declared with
  std::string companion;  // a flag the option is refused without ("--auto-disable")
  CLI::Option* parsed = nullptr;  // the command-line option, once added

  static Knob real(std::string name, std::string label, std::string unit, double& value, double min, double max);
  static Knob integer(std::string name, std::string label, int& value, int min, int max);
  static Knob interval(std::string name, std::string label, double& value, double min, double max);

  Knob& withOption(std::string optionName, std::string optionHelp);
  Knob& withKey(SDL_Keycode keyCode, std::string name, std::string description, std::vector<double> values = {});
  Knob& steppedBy(std::function<double(double, int)> next);
  Knob& zeroIsOff();
  Knob& logarithmic();
  Knob& rebuildsScene();
  Knob& onlyHeadless();
  Knob& defaultPickedByScene();
  Knob& onlyWith(std::string flag);
  // Up to infinity, which the option takes as "inf"; the panel's slider stops at sliderTop.
  Knob& upToInfinity(double sliderTop);
  // The option is parsed by the knob's owner (see ownParser).
  Knob& optionParsedByOwner();
  double panelMax() const { return sliderMax > 0 ? sliderMax : max; }

  double get() const;
  // Sets a value clamped to the range (0 kept where it means off; integers
  // rounded); returns "label from -> to unit", or "" when nothing changed.
  std::string set(double newValue);
  // The key's next value from the current one (direction -1 with Shift).
  double next(int direction) const;
  bool accepts(double candidate) const;
  std::string rangeText() const;  // "[1, 1e+09]", "0 (off) or [1e-06, 1e+06]", "[0, inf]"
  // The value as its option reads it back to the same double ("0.30000000000000004", "20").
  std::string optionText() const;
  // What the panel's row says beside the value, "" for a knob that acts at once:
  // "rebuilds the scene", "headless runs only".
  std::string effectText() const;
  // {"name": ..., "option": ..., "key": ..., "min": ..., "max": ..., "unit": ..., "default": ...,
  //  "kind": ..., "off_at_zero": ..., "only_with": ..., "scene_default": ...}
  std::string json() const;
};

// The JSON text of a string ("\"--erp\"").
std::string jsonString(const std::string& text);
// The JSON text of a number, exact for every double ("1e-06", "0.2");
// infinity as the string "inf" (mu's dInfinity).
std::string jsonNumber(double value);

}  // namespace odelab
