#pragma once

// One Bullet dynamics world and the world description it was built from:
// the objects Bullet needs alive together, the translation of the world's
// settings (ERP, CFM, iterations, gravity, restitution threshold, surface
// layer) and what EngineSetting::Best changes, and the per-object settings
// every body and static geom gets when it enters (sleeping, gravity,
// angular speed cap, continuous collision, contact rules).

#include <unordered_map>
#include <vector>

#include "BulletContacts.h"
#include "BulletShapes.h"
#include "world/Engine.h"

namespace odelab::engines::bullet {

// btDiscreteDynamicsWorld with ODE's per-body angular speed cap
// (dBodySetMaxAngularSpeed), applied where ODE applies it: after the
// velocities are solved, before the positions move.
class CappedDynamicsWorld : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
  std::unordered_map<btRigidBody*, double> caps;  // rad/s

 protected:
  void integrateTransforms(btScalar timeStep) override;
};

class BulletWorld {
 public:
  BulletWorld(world::EngineSetting setting, Notes& notes);

  // Takes the whole description (build, add); the surfaces and collide bits come with it.
  void describe(const world::World& world);
  // Takes the settings and surfaces only.
  void changeSettings(const world::World& world);
  world::World& description() { return description_; }
  const world::World& description() const { return description_; }
  btDiscreteDynamicsWorld& dynamics() { return dynamics_; }

  // A body described by `body` with the geoms `geoms` (their smallest half
  // size chooses Best's continuous collision), and a static geom.
  void add(btRigidBody& object, const world::Body& body, const std::vector<int>& geoms, double smallestHalfSize);
  void addStatic(btRigidBody& object, int geom);
  void remove(btRigidBody& object);

  // Joint `index` as Bullet builds it: Best's joint ERP replaces its own.
  world::Joint jointAsBuilt(int index) const;

  // The world's settings and surfaces into Bullet's solver (after every edit).
  void applySettings();
  int contactCount() const;

  static std::string bestSettingsText();

 private:
  void setUpSleeping(btRigidBody& object, const world::Body& body);
  void noteSettings();

  world::EngineSetting setting_;
  Notes& notes_;
  world::World description_;
  ContactRules rules_;  // before the dynamics world, whose broadphase calls it
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  CappedDynamicsWorld dynamics_;
  double idleSeconds_ = -1;  // ODE's auto-disable time of the first sleeping body, -1: none yet
};

}  // namespace odelab::engines::bullet
