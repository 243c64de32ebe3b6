// AbstractWindow, HUD: the text lines the window front end draws. The
// compact HUD (the default) keeps to what a user reads while tuning; F1
// switches to the full one and off.
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

#include "AbstractWindow.h"
#include "FormatValue.h"
#include "OdeMessages.h"
#include "SceneKeys.h"
#include "SpringDamper.h"
#include "WorldKnobs.h"

namespace odelab {

namespace {

// ERP and CFM as the spring and damper they mean at this step, and the ERP
// and CFM that would keep that spring at the next step size (F8).
std::string springLine(const WorldSettings& settings) {
  const SpringDamper spring = springDamperOf(settings.erp, settings.cfm, settings.step);
  if (spring.rigid)
    return "constraints rigid (CFM 0): no spring; ERP corrects " + formatValue(settings.erp) + " of the error per step";
  WorldSettings next = settings;
  next.step = ranges::STEP.clamp(nextStepSize(settings.step, +1));
  const ErpCfm keep = erpCfmFor(spring, next.step);
  std::ostringstream s;
  s << "spring kp " << formatValue(spring.kp) << " N/m, damper kd " << formatValue(spring.kd) << " N s/m; at step "
    << formatValue(next.step) << " keep them with ERP " << formatValue(keep.erp) << ", CFM " << formatValue(keep.cfm);
  return s.str();
}

// Every world setting with an F-key on one line: "ERP 0.2   CFM 1e-06   step 0.001 s ...";
// those that do not reach the engine shown last, after "not in jolt:".
std::string settingsLine(const std::deque<Knob>& knobs, const std::function<bool(const Knob&)>& reaches,
                         const std::string& engine) {
  std::string line, unreached;
  for (const Knob& knob : knobs) {
    if (!knob.appliesToWorld || knob.key == SDLK_UNKNOWN) continue;
    std::string& to = reaches(knob) ? line : unreached;
    if (!to.empty()) to += "   ";
    to += knob.label + ' ' + knob.words() + (knob.unit.empty() ? "" : " " + knob.unit);
  }
  if (!unreached.empty()) line += "   | not in " + engine + ": " + unreached;
  return line;
}

// Simulated time to the step's precision, so a single step (O) shows.
std::string timeText(double time, double step) {
  const int decimals = std::max(2, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, time);
  return text;
}

const char* shapeWord(Shape shape) {
  switch (shape) {
    case Shape::Box: return "box";
    case Shape::Sphere: return "sphere";
    case Shape::Capsule: return "capsule";
    case Shape::Cylinder: return "cylinder";
    case Shape::Plane: break;
  }
  return "plane";
}

}  // namespace

std::string AbstractWindow::headline() const {
  std::vector<std::string> sceneLines;
  addHudLines(sceneLines);
  return sceneLines.empty() ? std::string() : sceneLines.front();
}

std::vector<std::string> AbstractWindow::hudLines() const {
  std::vector<std::string> lines;
  if (session_.hudMode_ == HudMode::Off) return lines;
  const bool full = session_.hudMode_ == HudMode::Full;
  // On another engine the title says which, first thing read.
  const std::string engine = engine_.active() ? "   on " + engine_.engineName() +
                                                    (engine_.setting() == world::EngineSetting::Best ? " (best)" : "")
                                              : std::string();
  lines.push_back(title_ + engine + (full ? "" : "   (F1 more, H keys, Tab panel)"));
  lines.push_back(settingsLine(
      tuning_.knobs_, [this](const Knob& knob) { return knobNotReached(knob).empty(); }, engine_.engineName()));
  std::ostringstream s;
  char rate[96];
  // Paused, no simulated time passes: a factor would only say how long ago
  // the pause began.
  char factor[32] = "paused";
  if (!session_.time_.paused()) std::snprintf(factor, sizeof factor, "x%.2f", session_.time_.recentRealTimeFactor());
  std::snprintf(rate, sizeof rate, "FPS %.0f (%s)   real-time %s", session_.time_.recentFramesPerSecond(),
                frameLimitName(session_.time_.limit()), factor);
  s << rate << "   t=" << timeText(run_.simulatedTime_, tuning_.settings_.step) << " s   step " << run_.steps_;
  if (session_.time_.paused()) s << "   PAUSED (P runs, O steps)";
  lines.push_back(s.str());
  std::vector<std::string> sceneLines;
  addHudLines(sceneLines);
  // What the scene's own keys do, in a few words each (H lists them in full).
  std::string own;
  for (const KeyBinding* binding : sceneKeys(keys_)) own += (own.empty() ? "keys: " : "   ") + shortKeyText(*binding);
  if (!full) {
    if (!sceneLines.empty()) lines.push_back(sceneLines.front());
    if (!own.empty()) lines.push_back(own);
  } else {
    if (!own.empty()) lines.push_back(own);
    s.str("");
    s << "F2 increment " << formatValue(tuning_.increment_.value()) << "   space " << spaceKindName(run_.spaceKind_)
      << "   bodies " << bodyCount() << " (" << disabledBodyCount() << " disabled)   contacts " << run_.contactsLastStep_;
    lines.push_back(s.str());
    s.str("");
    s << "time scale x" << formatValue(session_.time_.scale()) << "   rewind , .  (" << session_.timeline().snapshotCount()
      << " snapshots)   dropped steps " << session_.time_.droppedSteps() << "   H help";
    lines.push_back(s.str());
    lines.push_back(springLine(tuning_.settings_));
    if (tuning_.contactChoicesUsed_)
      lines.push_back("contact mu " + ContactChoices::muWords(tuning_.contact_.mu) + " (F / G)   contacts per pair " +
                      std::to_string(tuning_.contact_.maxContacts));
    if (engine_.active()) {
      // Each engine's own words for what it could not take as ODE gave it.
      lines.push_back(engine_.engineName() + ": " + std::to_string(engine_.translationNotes().size()) +
                      " translation notes" + (engine_.translationNotes().empty() ? "" : " (first: " + engine_.translationNotes().front() + ")"));
    }
    lines.insert(lines.end(), sceneLines.begin(), sceneLines.end());
    if (const AbstractObject* object = draggedObject()) {
      const dReal* v = dBodyGetLinearVel(object->getBody());
      s.str("");
      s << "dragging object #" << session_.drag_.index() << " (" << shapeWord(object->shape()) << ", "
        << formatValue(object->mass()) << " kg), speed "
        << formatValue(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])) << " m/s";
      lines.push_back(s.str());
    }
  }
  // Lines that come and go stay at the end (hudPassingLines), so the ones
  // above keep their places.
  const std::vector<std::string> passing = hudPassingLines();
  lines.insert(lines.end(), passing.begin(), passing.end());
  return lines;
}

std::vector<std::string> AbstractWindow::hudPassingLines() const {
  std::vector<std::string> lines;
  if (session_.hudMode_ == HudMode::Off) return lines;
  if (!session_.failure_.empty()) lines.push_back(session_.failure_);
  if (rewindJob_.active) lines.push_back(rewindLine());
  const std::string current = session_.notice();
  if (!current.empty() && current != session_.failure_) lines.push_back(current);
  for (const auto& message : OdeMessages::recent()) lines.push_back(message);
  if (lines.empty()) lines.emplace_back();
  return lines;
}

}  // namespace odelab
