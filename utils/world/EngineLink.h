#pragma once

// A scene run on another engine (--engine): the engine steps, ODE does not.
// Before each step the link turns what the scene did to its ODE bodies since
// the last one (objects made or removed, a body moved, launched or pushed)
// into the engine's edits; after it, the engine's body states are written
// into the ODE bodies, so the scene's own measurements, HUD and files read
// the engine's world as they read ODE's.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "AbstractObject.h"
#include "Engine.h"
#include "WorldFromOde.h"

namespace odelab::world {

// A scene built from a world file: the file's own joints and surfaces, and
// which of them each ODE joint and geom was built from. The link hands an
// engine these rather than what ODE reads back, which holds values the file
// never set (the world's ERP copied into a joint, the infinite friction of a
// default surface that no pair uses).
struct FileOrigin {
  const World* world = nullptr;
  std::function<int(dGeomID)> geomOf;    // the file's geom index, or -1
  std::function<int(dJointID)> jointOf;  // the file's joint index, or -1
};

class EngineLink {
 public:
  bool active() const { return engine_ != nullptr; }
  const std::string& engineName() const { return name_; }
  EngineSetting setting() const { return setting_; }

  // Builds the scene's world, as ODE holds it now, in `engine`.
  // `file`: the world file the scene was built from, or null (a test program's scene).
  void start(std::unique_ptr<Engine> engine, const std::string& name, EngineSetting setting, Settings settings,
             const std::vector<std::unique_ptr<AbstractObject>>& objects, const SurfaceOf& surfaceOf,
             const FileOrigin* file = nullptr);
  // Builds the scene's world again in the engine running now, emptied in
  // place (Engine::reset); false, with nothing done, where it cannot be.
  bool restart(Settings settings, const std::vector<std::unique_ptr<AbstractObject>>& objects,
               const SurfaceOf& surfaceOf, const FileOrigin* file = nullptr);
  void stop() { engine_.reset(); }
  // The scene's changes since the last step, as edits.
  void sendEdits(const std::vector<std::unique_ptr<AbstractObject>>& objects, const SurfaceOf& surfaceOf);
  // New settings or surfaces (a knob changed).
  void changeSettings(const Settings& settings, const SurfaceOf& surfaceOf);
  // One engine step; its states written into the ODE bodies. Returns the
  // engine's own wall seconds for it.
  double step();
  int contactCount() const { return engine_->contactCount(); }
  const std::vector<std::string>& translationNotes() const { return engine_->translationNotes(); }
  double engineWallSeconds() const { return engine_->engineWallSeconds(); }
  double engineCpuSeconds() const { return engine_->engineCpuSeconds(); }
  // Wall seconds this program spent in the link outside the engine's own
  // collision and step calls: translating edits and settings, the pipe to an
  // engine in another process, the states copied back. The third cost beside
  // the engine's own calls and the whole run's CPU, never added to either.
  double linkWallSeconds() const { return linkWallSeconds_ - engine_->engineWallSeconds(); }
  const World& world() const { return world_; }

 private:
  void writeBack(int body, const BodyState& state);
  void forget(int body);  // removed from the engine and the index
  BodyState odeState(dBodyID body) const;
  // The file's values for the joints from `firstJoint` on and for every surface.
  void adoptFile(size_t firstJoint);
  void adoptFileSurfaces();

  std::unique_ptr<Engine> engine_;
  std::string name_;
  EngineSetting setting_ = EngineSetting::Default;
  World world_;
  OdeIndex index_;
  std::vector<BodyState> written_;  // per body: what was last written into its ODE body
  std::uint64_t bodyChanges_ = 0;
  FileOrigin file_;  // world null: no file
  double linkWallSeconds_ = 0.0;  // sendEdits, changeSettings and step as this program waits on them
};

}  // namespace odelab::world
