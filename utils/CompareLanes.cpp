#include "CompareLanes.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "OdeMessages.h"
#include "world/EngineCatalog.h"

namespace odelab {

namespace {

std::string versionOf(const std::string& engine) {
  for (const world::EngineInfo& info : world::knownEngines())
    if (info.name == engine) return info.version;
  return {};
}

// How much of a new frame's figure the smoothed time per step takes.
constexpr double SMOOTHING = 0.1;
// Below this real-time factor the window is behind real time.
constexpr double BEHIND = 0.99;

void addTiming(double& msPerStep, double seconds, long long steps) {
  if (steps <= 0) return;
  const double now = 1000.0 * seconds / static_cast<double>(steps);
  msPerStep = msPerStep > 0.0 ? (1.0 - SMOOTHING) * msPerStep + SMOOTHING * now : now;
}

// Two significant figures: "0.0071", "0.11", "1.4", "12"; whole from 100 ("110", not "1.1e+02").
std::string millisecondsText(double ms) {
  char text[32];
  std::snprintf(text, sizeof text, ms >= 100.0 ? "%.0f" : "%.2g", ms);
  return text;
}

}  // namespace

CompareLanes::CompareLanes(AbstractWindow& lead, const std::vector<std::pair<std::string, AbstractWindow*>>& others) {
  const auto laneOf = [](AbstractWindow* scene, const std::string& engine) {
    Lane lane;
    lane.scene = scene;
    lane.engine = engine;
    lane.version = versionOf(engine);
    return lane;
  };
  lanes_.push_back(laneOf(&lead, "ode"));
  for (const auto& [engine, scene] : others) lanes_.push_back(laneOf(scene, engine));
  // Every lane takes every input, one that stopped too: R or a knob then
  // holds when a rewind or a reset brings it back.
  lead.echoInputs([this](const TimelineEvent& event) {
    const auto start = std::chrono::steady_clock::now();
    for (size_t i = 1; i < lanes_.size(); ++i) {
      Lane& lane = lanes_[i];
      try {
        lane.scene->applyInput(event);
      } catch (const OdeError& error) {
        stop(lane, std::string("ODE error: ") + error.what());
      } catch (const world::EngineError& error) {
        stop(lane, error.what());
      }
    }
    longestInputSeconds_ =
        std::max(longestInputSeconds_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  });
}

CompareLanes::~CompareLanes() { lanes_.front().scene->echoInputs(nullptr); }

void CompareLanes::follow(double leadSeconds, long long leadSteps) {
  const AbstractWindow& lead = *lanes_.front().scene;
  const long long target = lead.run().steps();
  addTiming(lanes_.front().msPerStep, leadSeconds, leadSteps);
  lanes_.front().steppingSeconds += leadSeconds;
  for (size_t i = 1; i < lanes_.size(); ++i) {
    Lane& lane = lanes_[i];
    AbstractWindow& scene = *lane.scene;
    // R or a rewind took the lead back before the step this engine failed
    // on: it follows again, from its own record.
    if (!lane.failure.empty() && target < lane.failedAt) {
      lane.failure.clear();
      lane.failedAt = -1;
      scene.replayTo(target);
    }
    if (!lane.failure.empty()) continue;
    if (scene.run().steps() > target) scene.replayTo(target);  // a rewind
    const auto start = std::chrono::steady_clock::now();
    const long long before = scene.run().steps();
    try {
      while (scene.run().steps() < target) {
        if (!scene.stepOnce()) {
          stop(lane, scene.run().blowUpReason());
          break;
        }
      }
    } catch (const OdeError& error) {
      stop(lane, std::string("ODE error: ") + error.what());
    } catch (const world::EngineError& error) {
      stop(lane, error.what());
    }
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    addTiming(lane.msPerStep, took, scene.run().steps() - before);
    lane.steppingSeconds += took;
  }
}

void CompareLanes::stop(Lane& lane, const std::string& why) {
  if (!lane.failure.empty()) return;  // the first reason stands
  lane.failure = why;
  lane.failedAt = lane.scene->run().steps();
}

std::vector<std::string> CompareLanes::label(const Lane& lane) const {
  const AbstractWindow& scene = *lane.scene;
  std::string first = lane.engine + (lane.version.empty() ? "" : " " + lane.version);
  if (&lane == &lanes_.front()) {
    first += " (the scene's own settings)";
  } else {
    first += scene.engine().setting() == world::EngineSetting::Best ? " best" : " default";
    const size_t notes = scene.engine().translationNotes().size();
    if (notes) first += "   [" + std::to_string(notes) + (notes == 1 ? " note]" : " notes]");
  }
  if (!lane.failure.empty()) return {first, "stopped at step " + std::to_string(lane.failedAt) + ": " + lane.failure};
  const std::string headline = scene.headline();
  return headline.empty() ? std::vector<std::string>{first} : std::vector<std::string>{first, headline};
}

long long CompareLanes::stepsWithin(double seconds) const {
  double ms = 0.0;
  for (const Lane& lane : lanes_)
    if (lane.failure.empty()) ms += lane.msPerStep;
  if (ms <= 0.0) return 0;
  return std::max(1LL, static_cast<long long>(1000.0 * seconds / ms));
}

std::string CompareLanes::timingLine() const {
  const TimeControl& time = lanes_.front().scene->session().time();
  return timingLine(lanes_, !time.paused() && time.recentRealTimeFactor() < BEHIND);
}

std::string CompareLanes::timingLine(const std::vector<Lane>& lanes, bool behindRealTime) {
  // Items three spaces apart: the HUD wraps the line between them where it
  // is too wide (seven engines with the panel open at 1024x768).
  std::string steps = "ms/step:";
  const Lane* slowest = &lanes.front();
  for (const Lane& lane : lanes) {
    steps += (&lane == &lanes.front() ? " " : "   ") + lane.engine + " " +
             (lane.failure.empty() ? millisecondsText(lane.msPerStep) : "stopped");
    if (lane.failure.empty() && lane.msPerStep > slowest->msPerStep) slowest = &lane;
  }
  if (!behindRealTime) return steps;
  // First, so that a HUD row too narrow for every engine still names it.
  return "behind real time (slowest " + slowest->engine + ")   " + steps;
}

}  // namespace odelab
