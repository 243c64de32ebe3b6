// The scene as data, and the scene on another engine (--engine): the parts
// of AbstractWindow that reach utils/world.
#include <cmath>
#include <iostream>

#include "AbstractWindow.h"
#include "FormatValue.h"
#include "KnobReach.h"
#include "world/EngineCatalog.h"

namespace odelab {

world::SurfaceOf AbstractWindow::surfaceOf() {
  return [this](dGeomID a, dGeomID b, dSurfaceParameters& surface) { setContactSurface(a, b, surface); };
}

world::World AbstractWindow::describeWorld() {
  world::World described;
  described.scene = programName_;
  described.title = title_;
  described.time = run_.simulatedTime_;
  described.settings = world::settingsOf(run_.world_, tuning_.settings_, maxContacts(), spaceKindName(run_.spaceKind_));
  world::OdeIndex index;
  world::describeNewObjects(run_.objects_, surfaceOf(), described, index);
  return described;
}

void AbstractWindow::startEngine() {
  if (options_.engine == "ode") return;
  const world::EngineSetting setting = options_.engineBest ? world::EngineSetting::Best : world::EngineSetting::Default;
  const bool first = !engine_.active();
  try {
    // R and a rewind build the world again: in the engine running now where
    // it can be emptied in place (no new Node.js process), else in a new one.
    const world::Settings settings =
        world::settingsOf(run_.world_, tuning_.settings_, maxContacts(), spaceKindName(run_.spaceKind_));
    const bool same = !first && engine_.engineName() == options_.engine && engine_.setting() == setting;
    if (!same || !engine_.restart(settings, run_.objects_, surfaceOf(), fileOrigin()))
      engine_.start(world::makeEngine(options_.engine, setting), options_.engine, setting, settings, run_.objects_,
                    surfaceOf(), fileOrigin());
  } catch (const world::EngineFailure& error) {  // the engine failed: its kind kept (status 7, not 2)
    throw world::EngineFailure("engine " + options_.engine + ": " + error.what());
  } catch (const world::EngineError& error) {
    throw world::EngineError("engine " + options_.engine + ": " + error.what());
  }
  // Said once a run, on stderr, before any figure: what this engine could not express.
  if (first)
    for (const std::string& note : engine_.translationNotes())
      std::cerr << programName_ << " on " << options_.engine << ": translation note: " << note << '\n';
}

bool AbstractWindow::stepEngine() {
  const size_t notesBefore = engine_.translationNotes().size();
  try {
    engine_.sendEdits(run_.objects_, surfaceOf());
    run_.engineStepWallSeconds_ = engine_.step();
  } catch (const world::EngineFailure& error) {
    // Not the physics: the engine itself (its process, its protocol, its
    // deadline) failed, which the status and the metrics keep apart from a
    // blow-up so that no reader takes it for a stability limit.
    run_.blowUpReason_ = "engine " + options_.engine + " failed: " + error.what() + momentAndSettings();
    run_.engineFailed_ = true;
    return false;
  } catch (const world::EngineError& error) {
    // The engine answered, with a state that is not finite or an error of
    // its own while stepping: the run blew up on it, as on ODE (status 3).
    run_.blowUpReason_ = "simulation blew up on engine " + options_.engine + ": " + error.what() + momentAndSettings();
    return false;
  }
  const std::vector<std::string>& notes = engine_.translationNotes();
  for (size_t i = notesBefore; i < notes.size(); ++i)
    std::cerr << programName_ << " on " << options_.engine << ": translation note: " << notes[i] << '\n';
  const int contacts = engine_.contactCount();
  run_.contactsThisStep_ = contacts < 0 ? 0 : contacts;
  return true;
}

std::string AbstractWindow::knobNotReached(const Knob& knob) const {
  if (!engine_.active()) return {};
  return odelab::knobNotReached(knob.name, engine_.engineName(), engine_.translationNotes());
}

void AbstractWindow::engineSettingsChanged() {
  if (!engine_.active()) return;
  engine_.changeSettings(world::settingsOf(run_.world_, tuning_.settings_, maxContacts(), spaceKindName(run_.spaceKind_)),
                         surfaceOf());
}

}  // namespace odelab
