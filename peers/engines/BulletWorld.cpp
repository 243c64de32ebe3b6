#include "BulletWorld.h"

#include <algorithm>
#include <cmath>

namespace odelab::engines::bullet {

namespace {

// Best, each measured on the old scene-specific Bullet lab (peers/bullet_lab.cpp):
// - the sequential-impulse solver converges slowly across large mass ratios
//   (a 5000 kg cube on a 5 kg one, a chain of 1000:1 bodies): 100 iterations;
constexpr int BEST_ITERATIONS = 100;
// - Bullet's joint drift correction at ERP 0.2 lets a hinge drift and feeds
//   energy in and out of a pendulum; ERP 1 on every joint (its own ERP too)
//   closes the joint error each step;
constexpr double BEST_JOINT_ERP = 1.0;
// - continuous collision on every moving body: a body moving more than half
//   its smallest half size in a step is swept as a sphere of 0.9 of that
//   half size and stopped at the first hit (a small fast body cannot pass a
//   thin wall); slower bodies are untouched.
constexpr double CCD_MOTION_FRACTION = 0.5;
constexpr double CCD_SPHERE_FRACTION = 0.9;
// Exact bounce (only when a surface bounces): Bullet solves contacts that
// have not touched yet (speculative contacts) and pushes overlaps apart with
// velocity, both of which eat a bounce. Contact processing threshold 0 and
// contact ERP 0 (which also stops penetration recovery for every contact).

// Bullet's contact manifold holds at most this many points per shape pair.
constexpr int MANIFOLD_POINTS = 4;

}  // namespace

void CappedDynamicsWorld::integrateTransforms(btScalar timeStep) {
  for (auto& [body, cap] : caps) {
    const btVector3 w = body->getAngularVelocity();
    const double speed = w.length();
    if (speed > cap) body->setAngularVelocity(w * (cap / speed));
  }
  btDiscreteDynamicsWorld::integrateTransforms(timeStep);
}

BulletWorld::BulletWorld(world::EngineSetting setting, Notes& notes)
    : setting_(setting),
      notes_(notes),
      dispatcher_(&configuration_),
      dynamics_(&dispatcher_, &broadphase_, &solver_, &configuration_) {
  dynamics_.getPairCache()->setOverlapFilterCallback(&rules_);
}

void BulletWorld::describe(const world::World& world) {
  description_ = world;
  rules_.update(description_, notes_);
  noteShapeLimits(description_, notes_);
}

void BulletWorld::changeSettings(const world::World& world) {
  description_.settings = world.settings;
  description_.surfaces = world.surfaces;
  description_.defaultSurface = world.defaultSurface;
  description_.pairSurfaces = world.pairSurfaces;
  rules_.update(description_, notes_);
  applySettings();
}

void BulletWorld::add(btRigidBody& object, const world::Body& body, const std::vector<int>& geoms,
                      double smallestHalfSize) {
  // Gravity off: Bullet otherwise gives every body the world's when it enters.
  if (!body.gravity) object.setFlags(object.getFlags() | BT_DISABLE_WORLD_GRAVITY);
  rules_.attach(object, geoms, body.kinematic, notes_);
  dynamics_.addRigidBody(&object);
  if (!body.gravity) object.setGravity(btVector3(0, 0, 0));
  setUpSleeping(object, body);
  if (!std::isinf(body.maxAngularSpeed)) dynamics_.caps[&object] = body.maxAngularSpeed;
  if (setting_ == world::EngineSetting::Best && !body.kinematic && smallestHalfSize > 0) {
    object.setCcdMotionThreshold(CCD_MOTION_FRACTION * smallestHalfSize);
    object.setCcdSweptSphereRadius(CCD_SPHERE_FRACTION * smallestHalfSize);
  }
}

void BulletWorld::addStatic(btRigidBody& object, int geom) {
  rules_.attach(object, {geom}, true, notes_);
  dynamics_.addRigidBody(&object);
}

void BulletWorld::remove(btRigidBody& object) {
  dynamics_.removeRigidBody(&object);
  dynamics_.caps.erase(&object);
  rules_.detach(object);
}

// ODE's auto-disable as Bullet's sleeping, for the bodies that have it;
// every other body never sleeps (a body asleep as exported still starts
// asleep and wakes when touched).
void BulletWorld::setUpSleeping(btRigidBody& object, const world::Body& body) {
  if (body.kinematic) {
    object.forceActivationState(DISABLE_DEACTIVATION);
    return;
  }
  if (!body.autoDisable.on) {
    object.setSleepingThresholds(0, 0);
    object.forceActivationState(body.enabled ? DISABLE_DEACTIVATION : ISLAND_SLEEPING);
    return;
  }
  const world::AutoDisable& a = body.autoDisable;
  object.setSleepingThresholds(a.linearThreshold, a.angularThreshold);
  object.forceActivationState(body.enabled ? ACTIVE_TAG : ISLAND_SLEEPING);
  // ODE disables a body idle for `steps` steps and `time` seconds; Bullet
  // sleeps one idle longer than gDeactivationTime, one value for the process.
  const double h = description_.settings.step;
  const double idle = std::max(a.steps * h, a.time);
  if (idleSeconds_ < 0) {
    idleSeconds_ = idle;
    gDeactivationTime = std::max(idle - h / 2, h / 2);  // after the idle step itself, not one later
  } else if (idle != idleSeconds_) {
    notes_.add("ODE's auto-disable idle time differs between bodies; Bullet has one deactivation time for the "
               "world, " + number(idleSeconds_) + " s");
  }
  if (a.averageSamples > 1)
    notes_.add("ODE's auto-disable averages the speeds over " + std::to_string(a.averageSamples) +
               " steps; Bullet compares each step's speed with the thresholds");
  notes_.add("Bullet puts bodies to sleep a whole island at a time (bodies touching or joined), when every body "
             "in it has been idle; ODE disables each idle body");
}

world::Joint BulletWorld::jointAsBuilt(int index) const {
  world::Joint joint = description_.joints.at(static_cast<size_t>(index));
  if (setting_ == world::EngineSetting::Best) joint.erp = BEST_JOINT_ERP;
  return joint;
}

void BulletWorld::applySettings() {
  const world::Settings& s = description_.settings;
  const bool best = setting_ == world::EngineSetting::Best;
  dynamics_.setGravity(toBt(s.gravity));
  btContactSolverInfo& solver = dynamics_.getSolverInfo();
  // Joints use m_erp, contacts m_erp2; CFM is scaled by 1/step for both, as in ODE.
  solver.m_erp = best && !description_.joints.empty() ? BEST_JOINT_ERP : s.erp;
  const bool exactBounce = best && rules_.bounces();
  solver.m_erp2 = exactBounce ? 0.0 : s.erp;
  solver.m_globalCfm = s.cfm;
  solver.m_numIterations = best ? std::max(s.iterations, BEST_ITERATIONS) : s.iterations;
  // Penetration allowed without correction (dWorldSetContactSurfaceLayer).
  solver.m_linearSlop = s.contactSurfaceLayer;
  if (rules_.bounces()) solver.m_restitutionVelocityThreshold = rules_.restitutionThreshold();
  const double processing = exactBounce ? 0.0 : BT_LARGE_FLOAT;  // BT_LARGE_FLOAT: Bullet's default
  btCollisionObjectArray& objects = dynamics_.getCollisionObjectArray();
  for (int i = 0; i < objects.size(); ++i) objects[i]->setContactProcessingThreshold(processing);
  if (rules_.bounces() && !exactBounce)
    // What they do to a bounce is measured, not said here: the atlas's
    // bounce cases (doc/atlas-report/) have Bullet's default rising higher
    // than e^2 h, not lower.
    notes_.add("Bullet's default speculative contacts (solved before the shapes touch) change how high a body "
               "bounces (measured: doc/atlas-report/ATLAS.md); the best setting turns them off");
  noteSettings();
}

void BulletWorld::noteSettings() {
  const world::Settings& s = description_.settings;
  if (!s.quickStep)
    notes_.add("ODE's dWorldStep (a direct solver) has no Bullet equivalent: Bullet's sequential impulses ran " +
               std::to_string(dynamics_.getSolverInfo().m_numIterations) + " iterations");
  if (s.sorW != 1.0)
    notes_.add("ODE's SOR over-relaxation w = " + number(s.sorW) + " was not carried over: Bullet's solver keeps "
               "its relaxation 1");
  if (!std::isinf(s.contactMaxCorrectingVelocity))
    notes_.add("ODE caps a contact's correcting velocity at " + number(s.contactMaxCorrectingVelocity) +
               " m/s; Bullet has no such cap");
  if (s.maxContacts > MANIFOLD_POINTS)
    notes_.add("Bullet keeps at most " + std::to_string(MANIFOLD_POINTS) +
               " contact points per pair of shapes; ODE's max_contacts is " + std::to_string(s.maxContacts));
  // btRigidBody::integrateVelocities limits every body's rotation to a
  // quarter turn per step.
  notes_.add("Bullet caps every body's angular speed at pi/2 rad per step (" + number(SIMD_HALF_PI / s.step) +
             " rad/s at this step); ODE has no such cap");
}

int BulletWorld::contactCount() const {
  int count = 0;
  const btDispatcher& dispatcher = dispatcher_;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher_.getManifoldByIndexInternal(m);
    // The points the solver used: those within the processing threshold.
    for (int p = 0; p < manifold->getNumContacts(); ++p)
      count += manifold->getContactPoint(p).getDistance() <= manifold->getContactProcessingThreshold();
  }
  return count;
}

std::string BulletWorld::bestSettingsText() {
  return "at least " + std::to_string(BEST_ITERATIONS) +
         " solver iterations (sequential impulses converge slowly across large mass ratios "
         "[atlas: bullet default heavy-on-light-10 off; bullet best heavy-on-light-10 right]); joint ERP " +
         number(BEST_JOINT_ERP) +
         " on every joint, its own ERP included (Bullet's drift correction at 0.2 lets joints drift and feeds "
         "energy into a pendulum [atlas: bullet default double-pendulum-energy off; bullet best "
         "double-pendulum-energy right]); "
         "when a surface bounces, exact bounce: contact processing threshold 0 (no speculative contacts) and "
         "contact ERP 0 (no penetration recovery); continuous collision on every moving body (motion threshold " +
         number(CCD_MOTION_FRACTION) + " and swept sphere " + number(CCD_SPHERE_FRACTION) +
         " of its smallest half size)";
}

}  // namespace odelab::engines::bullet
