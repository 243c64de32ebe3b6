#pragma once

// One physics engine behind one small interface, so that a test program can
// run its scene on Bullet, MuJoCo, Havok, Jolt or Rapier and measure it with
// its own code. An adapter (peers/) knows nothing of any scene: it builds a
// world from its description (WorldDescription.h), takes the edits the scene
// makes as it runs, steps, and hands back every body's state.
//
// Bodies are named by their index in World::bodies; a body removed keeps its
// index (World::bodies[i].removed) so the others keep theirs.

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "WorldDescription.h"

namespace odelab::world {

// An engine that cannot run the world (a shape or joint it lacks, a body
// it cannot add): before the run, the program ends with status 2 naming the
// engine and this message.
class EngineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An engine that failed rather than refused: its process died or was
// killed, it answered what is not the protocol, or it missed a request's
// deadline. The run ends with exit_code::ENGINE_FAILED (7), before or
// during its steps; never read as physics. Any other EngineError while
// stepping (a state that is not finite, the engine's own error) is a
// blow-up on that engine (status 3).
class EngineFailure : public EngineError {
 public:
  using EngineError::EngineError;
};

struct BodyState {
  Vec3 position{0, 0, 0};  // centre of mass
  Quat orientation{1, 0, 0, 0};
  Vec3 linearVelocity{0, 0, 0};
  Vec3 angularVelocity{0, 0, 0};
  bool enabled = true;  // false: the engine has put it to sleep
};

// The engine's settings: its defaults, or its documented best for accuracy
// (doc/peers.md names them per engine). The step is always the world's.
enum class EngineSetting { Default, Best };

class Engine {
 public:
  virtual ~Engine() = default;
  // Builds every body, geom, joint and surface of `world`, at its settings.
  virtual void build(const World& world) = 0;
  // Bodies, geoms and joints appended to `world` since the last build or add
  // (indices from firstBody, firstGeom, firstJoint on), with the surfaces
  // their pairs need (already in world.surfaces / pairSurfaces).
  virtual void add(const World& world, int firstBody, int firstGeom, int firstJoint) = 0;
  virtual void remove(int body) = 0;  // the body, its geoms and its joints
  // The scene moved or pushed a body (a reset, a launch, a throw).
  virtual void setState(int body, const BodyState& state) = 0;
  // A force and torque (world frame, at the centre of mass) for the next step only.
  virtual void applyForce(int body, const Vec3& force, const Vec3& torque) = 0;
  // New world settings (a key or the panel), or new surfaces (mu changed).
  virtual void changeSettings(const World& world) = 0;
  virtual void step() = 0;  // one step of world.settings.step
  // Empties the engine for another build() (R, a rewind) where it can do so
  // in place, cheaper than a new one (an engine in another process keeps
  // its process and its loaded module); false where it cannot, and then a
  // new engine is made. Its notes and clocks start again.
  virtual bool reset() { return false; }
  virtual BodyState state(int body) const = 0;
  virtual int contactCount() const { return -1; }  // in the last step, or -1: unknown
  // What the engine could not express exactly, one sentence each, said once.
  virtual const std::vector<std::string>& translationNotes() const = 0;
  // Seconds spent in the engine's own collision and step calls so far (wall
  // and this process's CPU; an engine in another process reports its own).
  virtual double engineWallSeconds() const = 0;
  virtual double engineCpuSeconds() const = 0;
};

}  // namespace odelab::world
