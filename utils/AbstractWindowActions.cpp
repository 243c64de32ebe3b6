// AbstractWindow, actions: what a person does and how it is recorded. The
// knobs' declaration and their one change path, the key table and its
// dispatch, the panel's changes, the timeline of recorded inputs, the time
// and view keys, and the mouse drag. Keys, panel and replay meet in
// applyEvent().
#include <algorithm>

#include "AbstractWindow.h"
#include "FormatValue.h"
#include "MeasurementLog.h"
#include "OdeMessages.h"

namespace odelab {

void AbstractWindow::bindKey(SDL_Keycode key, std::string keyName, std::string description,
                             std::function<void(int)> action) {
  keys_.bind({key, std::move(keyName), std::move(description), std::move(action), true});
}

void AbstractWindow::bindViewKey(SDL_Keycode key, std::string keyName, std::string description,
                                 std::function<void(int)> action) {
  keys_.bind({key, std::move(keyName), std::move(description), std::move(action), false});
}

void AbstractWindow::rebindKey(SDL_Keycode key, std::string keyName, std::string description,
                               std::function<void(int)> action) {
  keys_.replace({key, std::move(keyName), std::move(description), std::move(action), true});
}

Knob& AbstractWindow::declare(Knob declared) {
  tuning_.knobs_.push_back(std::move(declared));
  Knob& knob = tuning_.knobs_.back();  // a deque keeps it in place as more are declared
  // Rewind puts back its value at the run's start before a replay.
  if (knob.count)
    session_.rewind_.keep(*knob.count);
  else if (knob.value)
    session_.rewind_.keep(*knob.value);
  else if (knob.on)
    session_.rewind_.keep(*knob.on);
  else if (knob.read && knob.write)
    session_.rewind_.keepThrough(knob.read, knob.write);
  Knob* stepped = &knob;
  if (knob.key != SDLK_UNKNOWN)
    keys_.bind({knob.key, knob.keyName, knob.keyHelp,
                [this, stepped](int direction) { stepKnob(*stepped, direction); }, true, true});
  if (knob.lowerKey != SDLK_UNKNOWN)
    keys_.bind({knob.lowerKey, knob.lowerKeyName, knob.lowerKeyHelp,
                [this, stepped](int direction) { stepKnob(*stepped, -direction); }, true, true});
  return knob;
}

// A knob's key: the next value on its ladder or by its stepper. At either
// end of its range or ladder the key changes nothing, and says so.
void AbstractWindow::stepKnob(Knob& knob, int direction) {
  const double before = knob.get();
  changeKnob(knob, knob.next(direction), "key");
  if (knob.get() != before || session_.rewind_.replaying()) return;
  const char* end = knob.ladder.empty() ? (direction > 0 ? " (the top of its range)" : " (the bottom of its range)")
                    : direction > 0     ? " (the ladder's top)"
                                        : " (the ladder's bottom)";
  notify(timeStamp(run_.simulatedTime_) + ": " + knob.label + " stays " + knob.words() + end);
}

void AbstractWindow::changeKnob(Knob& knob, double value, const char* source) {
  const bool byKey = std::string(source) == "key";
  const double oldErp = tuning_.settings_.erp, oldCfm = tuning_.settings_.cfm;
  const std::string change = knob.set(value);
  if (change.empty()) return;
  // Only an ERP or CFM change walks the joints; gravity, the step or the solver do not.
  if (tuning_.settings_.erp != oldErp || tuning_.settings_.cfm != oldCfm)
    run_.carryWorldErpCfmToJoints(oldErp, oldCfm, tuning_.settings_.erp, tuning_.settings_.cfm);
  logAction(byKey ? change : std::string(source) + ": " + change);
  engineSettingsChanged();
  if (knob.appliesToWorld) {
    applySettings(change);  // the world takes it at once; notifies, and tells the scene
    return;
  }
  if (knob.rebuilds) reset();  // a new value is a new experiment
  if (!session_.rewind_.replaying())
    notify(timeStamp(run_.simulatedTime_) + ": " + change + (knob.rebuilds ? "; scene rebuilt" : ""));
  onKnobChanged(knob);
}

bool AbstractWindow::handleKey(SDL_Keycode key, bool shift) {
  const KeyBinding* binding = keys_.find(key);
  if (!binding) return false;
  if (!binding->recorded || session_.rewind_.replaying()) {
    binding->action(shift ? -1 : +1);
    return true;
  }
  // A recorded key goes on the timeline, unless it began a new run (R).
  const long long epochBefore = session_.rewind_.epoch();
  const std::string name = (shift ? "Shift+" : "") + binding->keyName;
  const std::string description = binding->description;
  TimelineEvent event;
  event.step = run_.steps_;
  event.kind = TimelineEvent::Kind::Key;
  event.key = key;
  event.shift = shift;
  binding->action(shift ? -1 : +1);
  if (session_.rewind_.epoch() == epochBefore) session_.rewind_.record(event);
  if (echo_) echo_(event);
  // A knob's key logs the change it made (changeKnob); others their description.
  if (!binding->logsItself) logAction(name + ": " + description);
  return true;
}


void AbstractWindow::changeKnob(int index, double value) {
  if (index < 0 || index >= static_cast<int>(tuning_.knobs_.size())) return;
  TimelineEvent event;
  event.step = run_.steps_;
  event.kind = TimelineEvent::Kind::Knob;
  event.index = index;
  event.value = value;
  recordAndApply(event);
}

void AbstractWindow::recordAndApply(const TimelineEvent& event) {
  // An input that changes the run stops a rewind under way where it is:
  // the input belongs at the step shown.
  cancelRewind();
  // An input that rebuilt the scene began a new run: nothing to record.
  const long long epochBefore = session_.rewind_.epoch();
  applyEvent(event);
  if (session_.rewind_.epoch() == epochBefore) session_.rewind_.record(event);
  if (echo_) echo_(event);
}

void AbstractWindow::applyInput(const TimelineEvent& event) {
  if (event.kind == TimelineEvent::Kind::Key) {
    handleKey(event.key, event.shift);
    return;
  }
  if (event.kind == TimelineEvent::Kind::Knob && (event.index < 0 || event.index >= static_cast<int>(tuning_.knobs_.size())))
    return;
  TimelineEvent own = event;
  own.step = run_.steps_;
  // Logged as the leading scene's beginDrag and endDrag log them.
  const bool grabs = event.kind == TimelineEvent::Kind::Drag && !session_.drag_.active();
  const bool releases = event.kind == TimelineEvent::Kind::Release && session_.drag_.active();
  if (releases) session_.marks_.set("drag_end_distance", session_.drag_.gap(run_.objects_));
  recordAndApply(own);
  if (event.kind == TimelineEvent::Kind::Drag && session_.drag_.active())
    session_.marks_.set("drag_start_distance", session_.drag_.gap(run_.objects_));
  if (grabs) logAction("drag " + std::to_string(event.objectIndex));
  if (releases) logAction("release");
}

void AbstractWindow::applyEvent(const TimelineEvent& event) {
  switch (event.kind) {
    case TimelineEvent::Kind::Key:
      if (const KeyBinding* binding = keys_.find(event.key)) binding->action(event.shift ? -1 : +1);
      break;
    case TimelineEvent::Kind::Drag:
    case TimelineEvent::Kind::Release:
      session_.drag_.apply(event, static_cast<int>(run_.objects_.size()));
      break;
    case TimelineEvent::Kind::Knob:
      changeKnob(tuning_.knobs_[static_cast<size_t>(event.index)], event.value, "panel");
      break;
  }
}

void AbstractWindow::logAction(const std::string& text) {
  // The run log exists for windowed sessions, where a person acts; a replay
  // repeats what is logged already.
  if (options_.headless || session_.rewind_.replaying()) return;
  const std::string error = session_.runLog_.write(run_.simulatedTime_, run_.steps_, text);
  if (!error.empty()) notify(error);
}

void AbstractWindow::bindSharedKeys() {
  bindKey(SDLK_r, "R", "reset the scene to its initial state", [this](int) {
    // Named with the moment it left, as every change the run log records.
    const std::string at = timeStamp(run_.simulatedTime_);
    reset();
    notify(at + ": scene reset");
  });
  bindViewKey(SDLK_F1, "F1", "HUD: compact / full / off", [this](int) {
    session_.hudMode_ = session_.hudMode_ == HudMode::Compact ? HudMode::Full
               : session_.hudMode_ == HudMode::Full  ? HudMode::Off
                                            : HudMode::Compact;
  });
  keys_.bind({SDLK_F2, "F2", "choose the increment used by F3 / F4 (1e-6 ... 0.1)",
              [this](int d) {
                tuning_.increment_.cycle(d);
                const std::string change = "F2 increment " + formatValue(tuning_.increment_.value());
                logAction(change);
                applySettings(change);
              },
              true, true});
}

void AbstractWindow::offerSceneSwitch(std::vector<SceneChoice> scenes, int current) {
  const std::string list = scenes.front().name + " ... " + scenes.back().name + " (odelab --list)";
  session_.sceneChoices_ = std::move(scenes);
  session_.currentScene_ = current;
  bindViewKey(SDLK_PAGEDOWN, "PageDown", "next scene of " + list, [this](int) { session_.requestSceneSwitch(+1); });
  bindViewKey(SDLK_PAGEUP, "PageUp", "previous scene", [this](int) { session_.requestSceneSwitch(-1); });
}

void AbstractWindow::beginDrag(const PickHit& hit, const double target[3]) {
  TimelineEvent event;
  if (!MouseDrag::beginEvent(run_.objects_, hit, target, run_.steps_, event)) return;
  recordAndApply(event);
  session_.marks_.set("drag_start_distance", session_.drag_.gap(run_.objects_));
  logAction("drag " + std::to_string(hit.objectIndex));
}

void AbstractWindow::moveDrag(const double target[3]) {
  TimelineEvent event;
  if (!session_.drag_.moveEvent(target, run_.steps_, event)) return;
  recordAndApply(event);
  // The gap the spring now has to close (the renderer's beginDrag targets
  // the grabbed point itself, so the gap opens with the first move).
  session_.marks_.set("drag_start_distance", session_.drag_.gap(run_.objects_));
}

void AbstractWindow::endDrag() {
  TimelineEvent event;
  if (!session_.drag_.endEvent(run_.steps_, event)) return;
  session_.marks_.set("drag_end_distance", session_.drag_.gap(run_.objects_));
  recordAndApply(event);
  logAction("release");
}

const AbstractObject* AbstractWindow::draggedObject() const {
  return session_.drag_.active() ? run_.objects_[session_.drag_.index()].get() : nullptr;
}

void AbstractWindow::bindTimeAndViewKeys() {
  bindViewKey(SDLK_p, "P", "pause / resume", [this](int) { session_.time_.setPaused(!session_.time_.paused()); });
  bindViewKey(SDLK_o, "O", "advance exactly one step (pauses first)", [this](int) {
    cancelRewind();
    session_.time_.setPaused(true);
    try {
      if (!stepOnce()) recoverFrom(run_.blowUpReason_);
    } catch (const OdeError& error) {
      run_.stepThreading_ = nullptr;  // see advanceFrame()
      recoverFrom(std::string("ODE error: ") + error.what());
    }
  });
  bindViewKey(SDLK_MINUS, "-", "slower: halve the time scale (down to 1/32)", [this](int) { session_.time_.slower(); });
  bindViewKey(SDLK_EQUALS, "=", "faster: double the time scale (up to 8x, as far as the machine keeps up)",
              [this](int) { session_.time_.faster(); });
  bindViewKey(SDLK_COMMA, ",", "rewind to the previous snapshot (every 0.25 s of simulated time) and pause", [this](int) {
    // A press during a rewind goes a snapshot further back from its target.
    const long long from = rewinding() ? rewindTarget() : run_.steps_;
    rewindTo(std::max(0LL, session_.rewind_.timeline().previousSnapshot(from)), timeStamp(run_.simulatedTime_));
  });
  bindViewKey(SDLK_PERIOD, ".", "forward to the next snapshot or the furthest step reached, and pause", [this](int) {
    const long long target = session_.rewind_.timeline().nextSnapshot(rewinding() ? rewindTarget() : run_.steps_);
    session_.time_.setPaused(true);
    if (rewinding()) {  // the rewind under way stops a snapshot later
      if (target >= 0) rewindTo(target, timeStamp(run_.simulatedTime_));
      return;
    }
    if (target < 0) {
      notify("no later snapshot: press P to run on");
      return;
    }
    const std::string at = timeStamp(run_.simulatedTime_);
    while (run_.steps_ < target && stepOnce()) {
    }
    notify(at + ": forward to " + timeStamp(run_.simulatedTime_));
  });
  bindViewKey(SDLK_RETURN, "Enter", "dismiss the error message", [this](int) { session_.dismissFailure(); });
  bindViewKey(SDLK_h, "H", "help: this key list on / off", [this](int) { session_.viewFlags_.help = !session_.viewFlags_.help; });
  bindViewKey(SDLK_l, "L", "live plot of the scene's measurement on / off",
              [this](int) { session_.viewFlags_.plot = !session_.viewFlags_.plot; });
  bindViewKey(SDLK_c, "C", "contact points and normals on / off", [this](int) {
    session_.viewFlags_.contacts = !session_.viewFlags_.contacts;
    session_.contactMarkers_.clear();
  });
  bindViewKey(SDLK_j, "J", "joint anchors and axes on / off", [this](int) { session_.viewFlags_.joints = !session_.viewFlags_.joints; });
  bindViewKey(SDLK_x, "X", "bounding boxes on / off", [this](int) { session_.viewFlags_.boxes = !session_.viewFlags_.boxes; });
  bindViewKey(SDLK_v, "V", "wireframe on / off", [this](int) { session_.viewFlags_.wireframe = !session_.viewFlags_.wireframe; });
  bindViewKey(SDLK_F12, "F12", "save a screenshot (PNG named with the test and the simulated time) in --out-dir",
              [this](int) { session_.screenshotRequested_ = true; });
}

std::vector<std::string> AbstractWindow::helpLines() const {
  std::vector<std::string> lines = cameraHelpLines();
  lines.insert(lines.end(), {
      "Tab          control panel on / off",
      "Shift        reverses every F-key",
      "Esc          close the help (or a panel field), else quit (asks once if settings changed)",
  });
  for (const std::string& line : keys_.helpLines()) lines.push_back(line);
  return lines;
}

}  // namespace odelab
