// Bullet 3 (double precision, btDiscreteDynamicsWorld with its sequential
// impulse solver) behind world::Engine: builds any world description, steps
// it at the world's step with no substeps, and hands back every body's
// state. Shapes: BulletShapes; per-pair surfaces and collide bits:
// BulletContacts; joints: BulletJoints; the world and its settings:
// BulletWorld. This file holds the bodies and the edits a scene makes.
#include <cmath>
#include <time.h>

#include <chrono>

#include "Adapters.h"
#include "BulletJoints.h"
#include "BulletWorld.h"

namespace odelab::engines {

namespace bullet {
namespace {

using world::BodyState;

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The last state of a body the description holds but Bullet no longer does.
BodyState describedState(const world::Body& body) {
  BodyState s;
  s.position = body.position;
  s.orientation = body.orientation;
  s.linearVelocity = body.linearVelocity;
  s.angularVelocity = body.angularVelocity;
  s.enabled = body.enabled;
  return s;
}

struct BodyRecord {
  std::unique_ptr<btRigidBody> body;  // null once removed
  BodyShape shape;
  bool kinematic = false;
  // A kinematic body's pose (Bullet's frame) and velocities: it moves by them
  // alone, as ODE's kinematic bodies do.
  btTransform pose;
  btVector3 linear{0, 0, 0}, angular{0, 0, 0};
  BodyState removedState;
};

struct StaticRecord {
  std::unique_ptr<btCollisionShape> shape;
  std::unique_ptr<btRigidBody> object;
};

class BulletEngine : public world::Engine {
 public:
  explicit BulletEngine(world::EngineSetting setting) : world_(setting, notes_) {}
  ~BulletEngine() override {
    for (auto& joint : joints_)
      if (joint) world_.dynamics().removeConstraint(joint.get());
    for (auto& r : bodies_)
      if (r.body) world_.remove(*r.body);
    for (auto& s : statics_) world_.remove(*s.object);
  }

  void build(const world::World& world) override {
    world_.describe(world);
    addFrom(0, 0, 0);
  }

  void add(const world::World& world, int firstBody, int firstGeom, int firstJoint) override {
    std::vector<bool> removed;
    for (const BodyRecord& r : bodies_) removed.push_back(!r.body);
    world_.describe(world);
    for (size_t i = 0; i < removed.size(); ++i) world_.description().bodies[i].removed = removed[i];
    addFrom(firstBody, firstGeom, firstJoint);
  }

  void remove(int body) override {
    BodyRecord& r = record(body);
    if (!r.body) return;
    r.removedState = state(body);
    const auto& joints = world_.description().joints;
    for (size_t j = 0; j < joints.size(); ++j)
      if (joints_[j] && (joints[j].body1 == body || joints[j].body2 == body)) {
        world_.dynamics().removeConstraint(joints_[j].get());
        joints_[j].reset();
      }
    world_.remove(*r.body);
    r.body.reset();
    world_.description().bodies[body].removed = true;
  }

  void setState(int body, const BodyState& s) override {
    BodyRecord& r = record(body);
    if (!r.body) return;
    const btTransform pose(toBt(s.orientation) * r.shape.principal, toBt(s.position));
    btRigidBody& b = *r.body;
    b.setWorldTransform(pose);
    b.setInterpolationWorldTransform(pose);
    b.setLinearVelocity(toBt(s.linearVelocity));
    b.setAngularVelocity(toBt(s.angularVelocity));
    b.setInterpolationLinearVelocity(toBt(s.linearVelocity));
    b.setInterpolationAngularVelocity(toBt(s.angularVelocity));
    if (r.kinematic) {
      r.pose = pose;
      r.linear = toBt(s.linearVelocity);
      r.angular = toBt(s.angularVelocity);
    } else if (s.enabled) {
      b.activate(true);
    } else {
      b.forceActivationState(ISLAND_SLEEPING);
    }
    world_.dynamics().updateSingleAabb(&b);
  }

  void applyForce(int body, const world::Vec3& force, const world::Vec3& torque) override {
    BodyRecord& r = record(body);
    if (!r.body || r.kinematic) return;  // a kinematic body ignores forces, as in ODE
    r.body->applyCentralForce(toBt(force));
    r.body->applyTorque(toBt(torque));
    r.body->activate(true);
  }

  void changeSettings(const world::World& world) override { world_.changeSettings(world); }

  void step() override {
    const double h = world_.description().settings.step;
    for (BodyRecord& r : bodies_)
      if (r.body && r.kinematic) placeKinematicBefore(r, h);
    const auto wall0 = std::chrono::steady_clock::now();
    const double cpu0 = cpuSeconds();
    world_.dynamics().stepSimulation(h, 0);  // exactly one step of h: no substeps, no interpolation
    cpuSeconds_ += cpuSeconds() - cpu0;
    wallSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    for (BodyRecord& r : bodies_)
      if (r.body && r.kinematic) moveKinematicAfter(r, h);
  }

  BodyState state(int body) const override {
    const BodyRecord& r = bodies_.at(static_cast<size_t>(body));
    if (!r.body) return r.removedState;
    BodyState s;
    const btTransform& pose = r.kinematic ? r.pose : r.body->getWorldTransform();
    s.position = fromBt(pose.getOrigin());
    s.orientation = fromBt(pose.getRotation() * r.shape.principal.inverse());
    s.linearVelocity = fromBt(r.kinematic ? r.linear : r.body->getLinearVelocity());
    s.angularVelocity = fromBt(r.kinematic ? r.angular : r.body->getAngularVelocity());
    s.enabled = r.body->isActive();
    return s;
  }

  int contactCount() const override { return world_.contactCount(); }
  const std::vector<std::string>& translationNotes() const override { return notes_.list(); }
  double engineWallSeconds() const override { return wallSeconds_; }
  double engineCpuSeconds() const override { return cpuSeconds_; }

 private:
  BodyRecord& record(int body) {
    if (body < 0 || body >= static_cast<int>(bodies_.size()))
      throw world::EngineError("no body " + std::to_string(body) + " in this world");
    return bodies_[body];
  }

  void addFrom(int firstBody, int firstGeom, int firstJoint) {
    const world::World& w = world_.description();
    for (int i = firstBody; i < static_cast<int>(w.bodies.size()); ++i) addBody(i);
    std::vector<bool> reshape(w.bodies.size(), false);
    for (int g = firstGeom; g < static_cast<int>(w.geoms.size()); ++g) {
      const int body = w.geoms[g].body;
      if (body < 0)
        addStatic(g);
      else if (body < firstBody)
        reshape[body] = true;  // a geom added to a body that was already there
    }
    for (size_t i = 0; i < reshape.size(); ++i)
      if (reshape[i] && bodies_[i].body) reshapeBody(static_cast<int>(i));
    for (int j = firstJoint; j < static_cast<int>(w.joints.size()); ++j) addJoint(j);
    world_.applySettings();
  }

  void addBody(int index) {
    const world::Body& d = world_.description().bodies[index];
    bodies_.emplace_back();
    BodyRecord& r = bodies_.back();
    r.removedState = describedState(d);
    if (d.removed) return;
    r.shape = makeBodyShape(world_.description(), index);
    r.kinematic = d.kinematic;
    // A kinematic body has no mass in Bullet: contacts cannot move it.
    const double mass = d.kinematic ? 0.0 : d.mass;
    btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, r.shape.shape.get(),
                                                  d.kinematic ? btVector3(0, 0, 0) : r.shape.inertia);
    info.m_startWorldTransform = btTransform(toBt(d.orientation) * r.shape.principal, toBt(d.position));
    r.pose = info.m_startWorldTransform;
    r.body = std::make_unique<btRigidBody>(info);
    btRigidBody& b = *r.body;
    b.setLinearVelocity(toBt(d.linearVelocity));
    b.setAngularVelocity(toBt(d.angularVelocity));
    r.linear = toBt(d.linearVelocity);
    r.angular = toBt(d.angularVelocity);
    if (d.kinematic)  // mass 0 marked it static: it moves, only not by forces
      b.setCollisionFlags((b.getCollisionFlags() & ~btCollisionObject::CF_STATIC_OBJECT) |
                          btCollisionObject::CF_KINEMATIC_OBJECT);
    world_.add(b, d, geomsOf(index), r.shape.smallestHalfSize);
  }

  // A body whose geoms changed: a new shape, the same motion.
  void reshapeBody(int index) {
    BodyRecord& r = bodies_[index];
    const BodyState s = state(index);
    const world::Body& d = world_.description().bodies[index];
    world_.remove(*r.body);
    BodyShape shape = makeBodyShape(world_.description(), index);
    if (shape.principal.dot(r.shape.principal) < 1.0 - 1e-12)
      notes_.add("a geom added to a running body turned its principal axes: its joints keep the frames they had");
    r.body->setCollisionShape(shape.shape.get());
    if (!r.kinematic) r.body->setMassProps(d.mass, shape.inertia);
    r.shape = std::move(shape);  // the old shape goes only after the body let go of it
    world_.add(*r.body, d, geomsOf(index), r.shape.smallestHalfSize);
    setState(index, s);
  }

  void addStatic(int geom) {
    StaticRecord s;
    btTransform pose;
    s.shape = makeStaticShape(world_.description(), geom, pose);
    btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, s.shape.get());
    info.m_startWorldTransform = pose;
    s.object = std::make_unique<btRigidBody>(info);
    world_.addStatic(*s.object, geom);
    statics_.push_back(std::move(s));
  }

  void addJoint(int index) {
    world::Joint joint = world_.jointAsBuilt(index);
    // A joint with no ERP or CFM of its own takes the world's, as in ODE;
    // Bullet's constraints would take Bullet's own defaults instead.
    const world::Settings& settings = world_.description().settings;
    if (std::isnan(joint.erp)) joint.erp = settings.erp;
    if (std::isnan(joint.cfm)) joint.cfm = settings.cfm;
    auto bodyOf = [&](int body) -> btRigidBody* {
      if (body < 0) return nullptr;
      if (body >= static_cast<int>(bodies_.size()) || !bodies_[body].body)
        throw world::EngineError("joint " + std::to_string(index) + " names body " + std::to_string(body) +
                                 ", which is not in the world");
      return bodies_[body].body.get();
    };
    joints_.resize(world_.description().joints.size());
    joints_[index] = makeJoint(joint, bodyOf(joint.body1), bodyOf(joint.body2));
    // Joined bodies never touch, as in ODE's near callbacks.
    world_.dynamics().addConstraint(joints_[index].get(), true);
  }

  // Bullet gives a kinematic body the velocity that carries it from its
  // interpolation transform to its transform in one step: placing it at its
  // pose now, with the pose one step back, makes the contacts see it here
  // moving at its velocity, as ODE's do.
  static void placeKinematicBefore(BodyRecord& r, double h) {
    btTransform back;
    btTransformUtil::integrateTransform(r.pose, -r.linear, -r.angular, h, back);
    r.body->setWorldTransform(r.pose);
    r.body->setInterpolationWorldTransform(back);
  }
  static void moveKinematicAfter(BodyRecord& r, double h) {
    btTransform next;
    btTransformUtil::integrateTransform(r.pose, r.linear, r.angular, h, next);
    r.pose = next;
    r.body->setWorldTransform(next);
  }

  std::vector<int> geomsOf(int body) const {
    std::vector<int> geoms;
    const auto& all = world_.description().geoms;
    for (size_t g = 0; g < all.size(); ++g)
      if (all[g].body == body) geoms.push_back(static_cast<int>(g));
    return geoms;
  }

  Notes notes_;  // before world_, which notes as it is made
  BulletWorld world_;
  std::vector<BodyRecord> bodies_;  // by body index
  std::vector<StaticRecord> statics_;
  std::vector<std::unique_ptr<btTypedConstraint>> joints_;  // by joint index; null once removed
  double wallSeconds_ = 0, cpuSeconds_ = 0;
};

}  // namespace
}  // namespace bullet

world::EngineInfo bulletInfo() {
  world::EngineInfo info;
  info.name = "bullet";
  info.version = ODELAB_BULLET_VERSION;
  info.available = true;
  info.precision = "double";
  info.bestSettings = bullet::BulletWorld::bestSettingsText();
  return info;
}

std::unique_ptr<world::Engine> makeBullet(world::EngineSetting setting) {
  return std::make_unique<bullet::BulletEngine>(setting);
}

}  // namespace odelab::engines
