#include "SettingsTable.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "FormatValue.h"
#include "Knob.h"

namespace odelab {

const std::vector<SettingSpec>& settingsTable() {
  using S = WorldSettings;
  using P = ParameterStepper;
  static const std::vector<SettingSpec> table{
      {SettingId::Erp, "ERP", "--erp", "", SDLK_F3, "F3", "ERP up by the increment (Shift: down), within [0, 1]",
       "global error reduction parameter", &ranges::ERP, false, false, [](const S& s) { return s.erp; },
       [](S& s, double v) { s.erp = v; }, [](S& s, int d, const P& p) { p.stepErp(s, d); }, "erp", "ERP #", 1},
      {SettingId::Cfm, "CFM", "--cfm", "", SDLK_F4, "F4", "CFM up by the increment (Shift: down), within [0, 1]",
       "global constraint force mixing", &ranges::CFM, true, false, [](const S& s) { return s.cfm; },
       [](S& s, double v) { s.cfm = v; }, [](S& s, int d, const P& p) { p.stepCfm(s, d); }, "cfm", "CFM #", 2},
      {SettingId::Iterations, "iterations", "--iterations", "", SDLK_F6, "F6",
       "QuickStep iterations up (Shift: down): 1, 2, 3, 5, 8, 10, 15, 20, 30, 50 ... 1000", "QuickStep iterations",
       &ranges::ITERATIONS, true, true, [](const S& s) { return double(s.iterations); },
       [](S& s, double v) { s.iterations = static_cast<int>(std::lround(v)); },
       [](S& s, int d, const P&) { P::stepIterations(s, d); }, "iterations", "# iterations", 4},
      {SettingId::Sor, "SOR w", "--sor", "", SDLK_F7, "F7", "SOR relaxation w up by 0.05 (Shift: down), within [0.05, 1.95]",
       "QuickStep SOR over-relaxation w", &ranges::SOR, false, false, [](const S& s) { return s.sor; },
       [](S& s, double v) { s.sor = v; }, [](S& s, int d, const P&) { P::stepSor(s, d); }, "sor_w", "SOR w #", 5},
      {SettingId::Step, "step", "--step", "s", SDLK_F8, "F8", "step size up (Shift: down): 1e-5, 2e-5, 5e-5 ... 0.1 s",
       "simulation step size in seconds", &ranges::STEP, true, false, [](const S& s) { return s.step; },
       [](S& s, double v) { s.step = v; }, [](S& s, int d, const P&) { P::stepStepSize(s, d); }, "step_seconds", "step #", 0},
      {SettingId::Solver, "solver", "--solver", "", SDLK_F9, "F9", "switch solver: dWorldQuickStep / dWorldStep",
       "quick (dWorldQuickStep) or step (dWorldStep)", nullptr, false, true,
       [](const S& s) { return s.solver == Solver::QuickStep ? 0.0 : 1.0; },
       [](S& s, double v) { s.solver = v < 0.5 ? Solver::QuickStep : Solver::WorldStep; },
       [](S& s, int, const P&) { s.solver = s.solver == Solver::QuickStep ? Solver::WorldStep : Solver::QuickStep; },
       "solver", "solver #", 3},
  };
  return table;
}

const SettingSpec& settingSpec(SettingId id) {
  for (const SettingSpec& spec : settingsTable())
    if (spec.id == id) return spec;
  throw std::logic_error("settingSpec: no such setting");
}

double settingValue(const WorldSettings& s, SettingId id) { return settingSpec(id).get(s); }

void setSettingValue(WorldSettings& s, SettingId id, double value) {
  if (std::isnan(value)) return;
  const SettingSpec& spec = settingSpec(id);
  spec.set(s, spec.range ? spec.range->clamp(value) : value);
}

std::string settingText(SettingId id, double value) {
  if (id == SettingId::Solver) return value < 0.5 ? "quick" : "step";
  return formatValue(value);
}

namespace {

// The table in the order the reports list it.
std::vector<const SettingSpec*> inReportOrder() {
  std::vector<const SettingSpec*> specs;
  for (const SettingSpec& spec : settingsTable()) specs.push_back(&spec);
  std::sort(specs.begin(), specs.end(),
            [](const SettingSpec* a, const SettingSpec* b) { return a->reportRank < b->reportRank; });
  return specs;
}

}  // namespace

std::string settingsInForceText(const WorldSettings& settings) {
  std::string text;
  for (const SettingSpec* spec : inReportOrder()) {
    std::string words = spec->inMessage;
    words.replace(words.find('#'), 1, settingText(spec->id, settingValue(settings, spec->id)));
    text += (text.empty() ? " (" : ", ") + words;
  }
  return text + ")";
}

std::vector<std::pair<std::string, std::string>> settingsHeader(const WorldSettings& settings) {
  std::vector<std::pair<std::string, std::string>> header;
  for (const SettingSpec* spec : inReportOrder()) {
    const double value = settingValue(settings, spec->id);
    // A choice is written with what it calls in ODE: "quick (dWorldQuickStep)".
    std::string text = settingText(spec->id, value);
    if (!spec->range) text += value < 0.5 ? " (dWorldQuickStep)" : " (dWorldStep)";
    header.emplace_back(spec->header, text);
  }
  return header;
}

std::string settingJson(const SettingSpec& spec, const WorldSettings& settings) {
  const double value = settingValue(settings, spec.id);
  std::string text = "{\"name\": " + jsonString(spec.range ? spec.range->name : "solver") +
                     ", \"option\": " + jsonString(spec.option) + ", \"key\": " + jsonString(spec.keyName);
  if (spec.range)
    text += ", \"min\": " + jsonNumber(spec.range->min) + ", \"max\": " + jsonNumber(spec.range->max) +
            ", \"unit\": " + jsonString(spec.unit) + ", \"default\": " + jsonNumber(value) +
            ", \"kind\": " + jsonString(spec.integer ? "integer" : "real");
  else
    text += ", \"choices\": [\"quick\", \"step\"], \"unit\": \"\", \"default\": " + jsonString(settingText(spec.id, value)) +
            ", \"kind\": \"choice\"";
  return text + ", \"off_at_zero\": false, \"only_with\": \"\"}";
}

std::string SettingChange::text() const {
  return std::string(settingSpec(id).label) + ' ' + settingText(id, from) + " -> " + settingText(id, to);
}

SettingChange stepSetting(WorldSettings& s, SettingId id, int direction, const ParameterStepper& stepper) {
  SettingChange change{id, settingValue(s, id), 0};
  settingSpec(id).step(s, direction, stepper);
  change.to = settingValue(s, id);
  return change;
}

SettingChange assignSetting(WorldSettings& s, SettingId id, double value) {
  SettingChange change{id, settingValue(s, id), 0};
  setSettingValue(s, id, value);
  change.to = settingValue(s, id);
  return change;
}

}  // namespace odelab
