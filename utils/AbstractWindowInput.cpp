// AbstractWindow, input: the key table and its dispatch, the timeline of
// recorded inputs, the time and view keys, and the mouse drag.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "AbstractWindow.h"
#include "FormatValue.h"
#include "MeasurementLog.h"

namespace odelab {

namespace {
constexpr double MIN_TIME_SCALE = 1.0 / 32.0;
constexpr double MAX_TIME_SCALE = 8.0;
}  // namespace

void AbstractWindow::bindViewKey(SDL_Keycode key, std::string keyName, std::string description,
                                 std::function<void(int)> action) {
  bindKey(key, std::move(keyName), std::move(description), std::move(action));
  keyBindings_.back().recorded = false;
}

void AbstractWindow::bindKey(SDL_Keycode key, std::string keyName, std::string description,
                             std::function<void(int)> action) {
  // A scene binding replaces a shared one on the same key.
  keyBindings_.erase(std::remove_if(keyBindings_.begin(), keyBindings_.end(),
                                    [key](const KeyBinding& b) { return b.key == key; }),
                     keyBindings_.end());
  keyBindings_.push_back({key, std::move(keyName), std::move(description), std::move(action)});
}

bool AbstractWindow::handleKey(SDL_Keycode key, bool shift) {
  for (const auto& binding : keyBindings_) {
    if (binding.key != key) continue;
    if (!binding.recorded || replaying_) {
      binding.action(shift ? -1 : +1);
      return true;
    }
    // A recorded key goes on the timeline, unless it began a new run (R).
    const long long epochBefore = epoch_;
    lastChange_.clear();
    binding.action(shift ? -1 : +1);
    if (epoch_ == epochBefore) {
      TimelineEvent event;
      event.step = steps_;
      event.kind = TimelineEvent::Kind::Key;
      event.key = key;
      event.shift = shift;
      recordEvent(event);
    }
    logAction((shift ? "Shift+" : "") + binding.keyName + ": " +
              (lastChange_.empty() ? binding.description : lastChange_));
    return true;
  }
  return false;
}

void AbstractWindow::runBinding(SDL_Keycode key, bool shift) {
  for (const auto& binding : keyBindings_)
    if (binding.key == key) {
      binding.action(shift ? -1 : +1);
      return;
    }
}

void AbstractWindow::recordEvent(TimelineEvent event) {
  if (!replaying_) timeline_.record(event);
}

void AbstractWindow::applyEvent(const TimelineEvent& event) {
  switch (event.kind) {
    case TimelineEvent::Kind::Key:
      runBinding(event.key, event.shift);
      break;
    case TimelineEvent::Kind::Drag:
      dragIndex_ = event.objectIndex < static_cast<int>(objects_.size()) ? event.objectIndex : -1;
      std::copy(event.grab, event.grab + 3, dragGrab_);
      std::copy(event.target, event.target + 3, dragTarget_);
      break;
    case TimelineEvent::Kind::Release:
      dragIndex_ = -1;
      break;
  }
}

void AbstractWindow::logAction(const std::string& text) {
  // The run log exists for windowed sessions, where a person presses keys.
  if (options_.headless || runLogFailed_) return;
  if (!runLog_) {
    const std::string path = joinPath(options_.outDir, programName() + "_run_log.txt");
    runLog_ = std::fopen(path.c_str(), "w");
    if (!runLog_) {
      runLogFailed_ = true;
      notify("cannot write the run log '" + path + "'");
      return;
    }
    std::fprintf(runLog_, "# %s: inputs that changed the simulation, with their simulated time\n", title_.c_str());
  }
  std::fprintf(runLog_, "t=%.6g s (step %lld): %s\n", simulatedTime_, steps_, text.c_str());
  std::fflush(runLog_);
}

void AbstractWindow::stepSetting(const char* what, const std::function<void()>& change) {
  const WorldSettings before = settings_;
  change();
  std::ostringstream text;
  auto describe = [&](double from, double to) { text << what << ' ' << formatValue(from) << " -> " << formatValue(to); };
  const std::string name = what;
  if (name == "ERP") describe(before.erp, settings_.erp);
  else if (name == "CFM") describe(before.cfm, settings_.cfm);
  else if (name == "iterations") describe(before.iterations, settings_.iterations);
  else if (name == "SOR w") describe(before.sor, settings_.sor);
  else if (name == "step") describe(before.step, settings_.step);
  else if (name == "solver") text << "solver " << solverName(before.solver) << " -> " << solverName(settings_.solver);
  applySettings(text.str());
}

void AbstractWindow::bindSharedKeys() {
  bindKey(SDLK_ESCAPE, "Esc", "quit", [this](int) { quitRequested_ = true; });
  bindKey(SDLK_r, "R", "reset the scene to its initial state", [this](int) {
    reset();
    notify("scene reset");
  });
  bindKey(SDLK_F1, "F1", "HUD on / off", [this](int) { hudVisible_ = !hudVisible_; });
  bindKey(SDLK_F2, "F2", "choose the increment used by F3 / F4 (1e-6 ... 0.1)", [this](int d) {
    stepper_.cycleIncrement(d);
    applySettings("F2 increment " + formatValue(stepper_.increment()));
  });
  bindKey(SDLK_F3, "F3", "ERP up by the increment (Shift: down), within [0, 1]",
          [this](int d) { stepSetting("ERP", [&] { stepper_.stepErp(settings_, d); }); });
  bindKey(SDLK_F4, "F4", "CFM up by the increment (Shift: down), within [0, 1]",
          [this](int d) { stepSetting("CFM", [&] { stepper_.stepCfm(settings_, d); }); });
  bindKey(SDLK_F6, "F6", "QuickStep iterations up (Shift: down): 1, 2, 3, 5, 8, 10, 15, 20, 30, 50 ... 1000",
          [this](int d) { stepSetting("iterations", [&] { ParameterStepper::stepIterations(settings_, d); }); });
  bindKey(SDLK_F7, "F7", "SOR relaxation w up by 0.05 (Shift: down), within [0.05, 1.95]",
          [this](int d) { stepSetting("SOR w", [&] { ParameterStepper::stepSor(settings_, d); }); });
  bindKey(SDLK_F8, "F8", "step size up (Shift: down): 1e-5, 2e-5, 5e-5 ... 0.1 s",
          [this](int d) { stepSetting("step", [&] { ParameterStepper::stepStepSize(settings_, d); }); });
  bindKey(SDLK_F9, "F9", "switch solver: dWorldQuickStep / dWorldStep", [this](int) {
    stepSetting("solver", [&] {
      settings_.solver = settings_.solver == Solver::QuickStep ? Solver::WorldStep : Solver::QuickStep;
    });
  });
}

PickHit AbstractWindow::pickAt(const double origin[3], const double direction[3]) const {
  return pickObject(objects_, origin, direction);
}

void AbstractWindow::beginDrag(const PickHit& hit, const double target[3]) {
  if (hit.objectIndex < 0 || hit.objectIndex >= static_cast<int>(objects_.size())) return;
  const dBodyID body = objects_[hit.objectIndex]->getBody();
  if (!body) return;
  dVector3 local;
  dBodyGetPosRelPoint(body, hit.point[0], hit.point[1], hit.point[2], local);
  TimelineEvent event;
  event.step = steps_;
  event.kind = TimelineEvent::Kind::Drag;
  event.objectIndex = hit.objectIndex;
  std::copy(local, local + 3, event.grab);
  std::copy(target, target + 3, event.target);
  applyEvent(event);
  recordEvent(event);
  marks_.set("drag_start_distance", DragSpring::distance(body, dragGrab_, dragTarget_));
  logAction("drag " + std::to_string(hit.objectIndex));
}

void AbstractWindow::moveDrag(const double target[3]) {
  if (dragIndex_ < 0) return;
  TimelineEvent event;
  event.step = steps_;
  event.kind = TimelineEvent::Kind::Drag;
  event.objectIndex = dragIndex_;
  std::copy(dragGrab_, dragGrab_ + 3, event.grab);
  std::copy(target, target + 3, event.target);
  applyEvent(event);
  recordEvent(event);
  // The gap the spring now has to close (the renderer's beginDrag targets
  // the grabbed point itself, so the gap opens with the first move).
  if (const dBodyID body = objects_[dragIndex_]->getBody())
    marks_.set("drag_start_distance", DragSpring::distance(body, dragGrab_, dragTarget_));
}

void AbstractWindow::endDrag() {
  if (dragIndex_ < 0) return;
  if (const dBodyID body = objects_[dragIndex_]->getBody())
    marks_.set("drag_end_distance", DragSpring::distance(body, dragGrab_, dragTarget_));
  TimelineEvent event;
  event.step = steps_;
  event.kind = TimelineEvent::Kind::Release;
  applyEvent(event);
  recordEvent(event);
  logAction("release");
}

const AbstractObject* AbstractWindow::draggedObject() const {
  return dragIndex_ >= 0 ? objects_[dragIndex_].get() : nullptr;
}

void AbstractWindow::bindTimeAndViewKeys() {
  bindViewKey(SDLK_p, "P", "pause / resume", [this](int) { paused_ = !paused_; });
  bindViewKey(SDLK_o, "O", "advance exactly one step (pauses first)", [this](int) {
    paused_ = true;
    if (!stepOnce()) {
      const std::string reason = blowUpReason_;
      reset();
      notify(reason + "; scene reset");
    }
  });
  bindViewKey(SDLK_MINUS, "-", "slower: halve the time scale (down to 1/32)",
              [this](int) { timeScale_ = std::max(MIN_TIME_SCALE, timeScale_ * 0.5); });
  bindViewKey(SDLK_EQUALS, "=", "faster: double the time scale (up to 8x, as far as the machine keeps up)",
              [this](int) { timeScale_ = std::min(MAX_TIME_SCALE, timeScale_ * 2.0); });
  bindViewKey(SDLK_COMMA, ",", "rewind to the previous snapshot (every 0.25 s of simulated time) and pause", [this](int) {
    const long long target = std::max(0LL, timeline_.previousSnapshot(steps_));
    replayTo(target);
    notify("rewound to t=" + formatValue(simulatedTime_) + " s");
  });
  bindViewKey(SDLK_PERIOD, ".", "forward to the next snapshot, replaying what was recorded, and pause", [this](int) {
    const long long target = timeline_.nextSnapshot(steps_);
    paused_ = true;
    if (target < 0) {
      notify("no later snapshot: press P to run on");
      return;
    }
    while (steps_ < target && stepOnce()) {
    }
    notify("forward to t=" + formatValue(simulatedTime_) + " s");
  });
  bindViewKey(SDLK_h, "H", "help: this key list on / off", [this](int) { viewFlags_.help = !viewFlags_.help; });
  bindViewKey(SDLK_l, "L", "live plot of the scene's measurement on / off",
              [this](int) { viewFlags_.plot = !viewFlags_.plot; });
  bindViewKey(SDLK_c, "C", "contact points and normals on / off", [this](int) {
    viewFlags_.contacts = !viewFlags_.contacts;
    contactMarkers_.clear();
  });
  bindViewKey(SDLK_j, "J", "joint anchors and axes on / off", [this](int) { viewFlags_.joints = !viewFlags_.joints; });
  bindViewKey(SDLK_x, "X", "bounding boxes on / off", [this](int) { viewFlags_.boxes = !viewFlags_.boxes; });
  bindViewKey(SDLK_v, "V", "wireframe on / off", [this](int) { viewFlags_.wireframe = !viewFlags_.wireframe; });
  bindViewKey(SDLK_F12, "F12", "save a screenshot (PNG named with the test and the simulated time) in --out-dir",
              [this](int) { screenshotRequested_ = true; });
}

std::vector<std::string> AbstractWindow::helpLines() const {
  std::vector<std::string> lines{
      "left mouse   on a body: drag it with a spring; elsewhere: toggle mouse-look",
      "W/S/A/D      move the camera forward / back / left / right along the view",
      "mouse wheel  move the camera forward / back, 0.5 m a notch",
      "Shift        reverses every F-key",
  };
  for (const auto& binding : keyBindings_) {
    std::string name = binding.keyName;
    name.resize(std::max<size_t>(name.size(), 12), ' ');
    lines.push_back(name + " " + binding.description);
  }
  return lines;
}

}  // namespace odelab
