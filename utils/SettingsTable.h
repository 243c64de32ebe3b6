#pragma once

#include <SDL2/SDL_keycode.h>

#include <string>
#include <utility>
#include <vector>

#include "WorldSettings.h"

namespace odelab {

// The world settings a user tunes, as one table: the F-keys, the command
// line, the control panel, the HUD and the run log are all built from it,
// so a setting's name, range and key are written once.
enum class SettingId { Erp, Cfm, Iterations, Sor, Step, Solver };

struct SettingSpec {
  SettingId id;
  const char* label;   // on the HUD, the panel and in change messages: "ERP"
  const char* option;  // on the command line: "--erp"
  const char* unit;    // "" or "s"
  SDL_Keycode key;     // the thesis's F-key
  const char* keyName;
  const char* keyHelp;
  const char* optionHelp;
  const ParameterRange* range;  // nullptr for the solver (a choice of two)
  bool logScale;                // the panel's slider: CFM and the step span decades
  bool integer;
  // The field in WorldSettings, as a number (the solver: 0 QuickStep, 1 dWorldStep).
  double (*get)(const WorldSettings& settings);
  void (*set)(WorldSettings& settings, double value);  // value already clamped
  // One F-key press: the F2 increment (ERP, CFM), the ladder, or the other solver.
  void (*step)(WorldSettings& settings, int direction, const ParameterStepper& stepper);
  // How the reports name it: the output files' header key ("step_seconds"),
  // its words in the blow-up and ODE error messages ("# iterations", #: the
  // value), and its place in both (they list step first, as ODE's manual).
  const char* header;
  const char* inMessage;
  int reportRank;
};

const std::vector<SettingSpec>& settingsTable();
const SettingSpec& settingSpec(SettingId id);

// A setting's value as a number (the solver: 0 QuickStep, 1 dWorldStep).
double settingValue(const WorldSettings& settings, SettingId id);
// Sets a value, clamped to the setting's range (integers rounded).
void setSettingValue(WorldSettings& settings, SettingId id, double value);
// "0.2", "20", "quick".
std::string settingText(SettingId id, double value);

// " (step 0.001, ERP 0.2, CFM 1e-06, solver quick, 20 iterations, SOR w 1.3)":
// every setting of the table, for the end of blow-up and ODE error messages.
std::string settingsInForceText(const WorldSettings& settings);
// Every setting of the table as output-file header pairs: {"step_seconds", "0.001"}, ...
std::vector<std::pair<std::string, std::string>> settingsHeader(const WorldSettings& settings);

// {"name": "erp", "option": "--erp", "key": "F3", "min": 0, "max": 1, "unit": "", "default": 0.2}
// (the solver: "choices" in place of min and max).
std::string settingJson(const SettingSpec& spec, const WorldSettings& settings);

// What one action did to a setting.
struct SettingChange {
  SettingId id;
  double from, to;
  bool changed() const { return from != to; }
  std::string text() const;  // "ERP 0.2 -> 0.21"
};

// One F-key press: the next value by the F2 increment (ERP, CFM) or the
// setting's ladder (iterations, SOR, step), or the other solver.
SettingChange stepSetting(WorldSettings& settings, SettingId id, int direction, const ParameterStepper& stepper);
// A typed or dragged value from the panel.
SettingChange assignSetting(WorldSettings& settings, SettingId id, double value);

}  // namespace odelab
