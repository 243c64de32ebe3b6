#pragma once

#include <SDL2/SDL_keycode.h>

#include <functional>
#include <string>
#include <vector>

namespace CLI {
class Option;
}

namespace odelab {

// What a knob's number is: any value in its range, a whole number, a span
// of simulated time that has to hold at least one step (a row, a spawn, a
// throw per step at most), one of a few named choices (its index), or a
// switch (1 on, 0 off; its option is a flag, given to turn it on).
enum class KnobKind { Real, Integer, Interval, Choice, Switch };

// Where the panel shows a knob, under one header each.
enum class KnobGroup { World, Contacts, Scene };

// One value a person tunes, declared once like a row of MuJoCo's UI table:
// the world settings (ERP, CFM, step, solver, iterations, SOR, gravity;
// utils/WorldKnobs.cpp), the contact choices (mu, contacts per pair) and
// each scene's own. The command line, the keys, the control panel, the HUD,
// the output files' headers, the blow-up and error messages, the metrics
// (knob_<name>), the run log, rewind, the copied command line and
// --list-settings all read these declarations in one loop each, so a
// value's name, range and key are written once.
struct Knob {
  std::string name;   // in --list-settings and the metrics: "big_mass" (knob_big_mass)
  std::string label;  // on the panel, the HUD and in change messages: "big cube mass"
  std::string unit;   // "kg", "" for none
  // Where the value lives: a double (Real, Interval), an int (Integer), or
  // for a choice stored as something else (the solver's enum) a reader and
  // a writer of its index.
  double* value = nullptr;
  int* count = nullptr;
  bool* on = nullptr;  // Switch
  std::function<double()> read;
  std::function<void(double)> write;
  double min = 0, max = 0;  // max is infinity where the option takes "inf" (mu)
  double sliderMax = 0;     // the panel slider's top where max is infinity
  KnobKind kind = KnobKind::Real;
  std::vector<std::string> choices;      // Choice: the option's words ("quick", "step")
  std::vector<std::string> choiceNames;  // Choice: what each calls in ODE ("dWorldQuickStep")
  KnobGroup group = KnobGroup::Scene;
  bool offAtZero = false;  // 0 is accepted too, below min, and means "off"
  std::string option;      // "--big-mass"
  std::string help;        // --help's line and the panel's tooltip
  SDL_Keycode key = SDLK_UNKNOWN;  // steps the value (Shift: back)
  std::string keyName, keyHelp;
  SDL_Keycode lowerKey = SDLK_UNKNOWN;  // a second key that steps it back (mu's F beside G)
  std::string lowerKeyName, lowerKeyHelp;
  std::vector<double> ladder;  // the keys' values, ascending; empty: the knob's stepper
  std::function<double(double current, int direction)> stepper;
  bool logScale = false;  // the panel's slider spans decades
  bool rebuilds = false;  // a new value starts a new run (the scene is built again)
  bool headlessOnly = false;  // only a headless run reads it (throws, launches)
  bool appliesToWorld = false;  // a world setting: a change reaches the ODE world at once
  // Its declared value stands for a default the scene picks itself (headless
  // or window, scanning or not): the copied command line names it only once
  // it is given or changed, so that the line leaves that choice to the scene.
  bool sceneDefault = false;
  double initial = 0;  // the value it was declared with
  std::string companion;  // a flag the option is refused without ("--auto-disable")
  // The output files' header key ("step_seconds"); the name where empty.
  std::string header;
  // Its words at the end of blow-up and ODE error messages, '#' standing for
  // the value ("ERP #"); "" keeps it out of them.
  std::string inMessage;
  // Its place among the world settings in headers and messages (they list
  // the step first, as ODE's manual); the others follow in declaration order.
  int reportRank = 0;
  CLI::Option* parsed = nullptr;  // the command-line option, once added

  static Knob real(std::string name, std::string label, std::string unit, double& value, double min, double max);
  static Knob integer(std::string name, std::string label, int& value, int min, int max);
  static Knob interval(std::string name, std::string label, double& value, double min, double max);
  static Knob toggle(std::string name, std::string label, bool& on);
  static Knob choice(std::string name, std::string label, std::vector<std::string> words,
                     std::vector<std::string> odeNames, std::function<int()> get, std::function<void(int)> set);

  Knob& withOption(std::string optionName, std::string optionHelp);
  Knob& withKey(SDL_Keycode keyCode, std::string name, std::string description, std::vector<double> values = {});
  Knob& withLowerKey(SDL_Keycode keyCode, std::string name, std::string description);
  Knob& steppedBy(std::function<double(double, int)> next);
  Knob& zeroIsOff();
  Knob& logarithmic();
  Knob& rebuildsScene();
  Knob& onlyHeadless();
  Knob& defaultPickedByScene();
  Knob& onlyWith(std::string flag);
  Knob& inGroup(KnobGroup where);
  // Up to infinity, which the option takes as "inf"; the panel's slider stops at sliderTop.
  Knob& upToInfinity(double sliderTop);
  // A world setting: applied to the world on change, reported under `headerKey`
  // and, where `messageWords` is not "", in blow-up and error messages.
  Knob& worldSetting(std::string headerKey, std::string messageWords, int rank);
  double panelMax() const { return sliderMax > 0 ? sliderMax : max; }
  double panelMin() const { return offAtZero ? 0.0 : min; }

  double get() const;
  // Sets a value clamped to the range (0 kept where it means off; integers
  // and choices rounded); returns "label from -> to unit", or "" when nothing changed.
  std::string set(double newValue);
  // The keys' next value from the current one (direction -1 with Shift or the lower key).
  double next(int direction) const;
  bool accepts(double candidate) const;
  // A value for people: "0.2", "quick", "infinite".
  std::string words(double v) const;
  std::string words() const { return words(get()); }
  std::string rangeText() const;  // "[1, 1e+09]", "0 (off) or [1e-06, 1e+06]", "[0, inf]", "quick or step"
  // The value as its option reads it back to the same double ("0.30000000000000004", "20", "inf", "quick").
  std::string optionText() const;
  // The output files' header: six digits, "dInfinity", "quick (dWorldQuickStep)".
  std::string headerText() const;
  std::string headerKey() const { return header.empty() ? name : header; }
  // The metric knob_<name>: the number, the choice's index, -1 for infinity
  // (JSON has none; only knobs that cannot be negative reach it).
  double metricValue() const;
  // What the panel's row says beside the value, "" for a knob that acts at once:
  // "rebuilds the scene", "headless runs only".
  std::string effectText() const;
  // The option's text as a value: a number, inf / infinity / dInfinity where
  // the range reaches infinity, or one of the choices; NaN when it is none.
  double parse(const std::string& text) const;
};

// The JSON number text of a double, the shortest that reads back the same
// ("1e-06", "0.2"): what the copied command line and the options take back.
std::string shortestNumber(double value);

// The next value after `current` in an ascending ladder (direction +1) or
// the previous one (-1); stays at the ends.
double nextOnLadder(const std::vector<double>& ladder, double current, int direction);

}  // namespace odelab
