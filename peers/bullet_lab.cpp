// bullet_lab: the thesis's measurement scenes on Bullet 3 (double precision,
// btDiscreteDynamicsWorld with its sequential-impulse solver), built with the
// same geometry, masses, gravity and step as the ODE programs. Settings per
// scene ("default" and "best") are named in settingText and doc/peers.md.
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <memory>
#include <vector>

#include "PeerScene.h"
#include "Test10Scene.h"
#include "WorldSettings.h"
#include "shared/SceneConstants.h"

namespace {

using namespace odelab;
using namespace odelab::peers;

Vec3 toVec3(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

// One Bullet world and everything in it, deleted together.
class BulletWorld {
 public:
  explicit BulletWorld(double gravity)
      : dispatcher_(&configuration_), world_(&dispatcher_, &broadphase_, &solver_, &configuration_) {
    world_.setGravity(btVector3(0, -gravity, 0));
  }
  ~BulletWorld() {
    for (int i = world_.getNumConstraints() - 1; i >= 0; --i) world_.removeConstraint(world_.getConstraint(i));
    for (auto& body : bodies_) world_.removeRigidBody(body.get());
  }

  // A body with its centre of mass at `position`; mass 0 makes it static.
  // `inertia`: principal moments about the centre; (0,0,0) lets the shape
  // compute them (exact for boxes and spheres).
  btRigidBody* add(btCollisionShape* shape, double mass, const btVector3& position,
                   btVector3 inertia = btVector3(0, 0, 0)) {
    shapes_.emplace_back(shape);
    if (mass > 0 && inertia.isZero()) shape->calculateLocalInertia(mass, inertia);
    btTransform start;
    start.setIdentity();
    start.setOrigin(position);
    motionStates_.push_back(std::make_unique<btDefaultMotionState>(start));
    btRigidBody::btRigidBodyConstructionInfo info(mass, motionStates_.back().get(), shape, inertia);
    bodies_.push_back(std::make_unique<btRigidBody>(info));
    btRigidBody* body = bodies_.back().get();
    // The scenes run with sleeping off (as test4 turns ODE's auto-disable
    // off): a body put to sleep would hide the behaviour being measured.
    body->setActivationState(DISABLE_DEACTIVATION);
    world_.addRigidBody(body);
    return body;
  }

  void keep(btTypedConstraint* constraint) {
    constraints_.emplace_back(constraint);
    world_.addConstraint(constraint);
  }

  // Fixed step, no substeps or interpolation (Bullet's default of
  // stepSimulation(h) would run 1/60 s substeps).
  void step(double h) { world_.stepSimulation(h, 0); }
  btContactSolverInfo& solverInfo() { return world_.getSolverInfo(); }
  btDiscreteDynamicsWorld& world() { return world_; }

  // Deepest overlap among all contact points, m (0 when none overlaps).
  double deepestPenetration() {
    double deepest = 0.0;
    for (int m = 0; m < dispatcher_.getNumManifolds(); ++m) {
      btPersistentManifold* manifold = dispatcher_.getManifoldByIndexInternal(m);
      for (int p = 0; p < manifold->getNumContacts(); ++p)
        deepest = std::max<double>(deepest, -manifold->getContactPoint(p).getDistance());
    }
    return deepest;
  }

 private:
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btMotionState>> motionStates_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<std::unique_ptr<btTypedConstraint>> constraints_;
};

// ---- test2 / test8 ---------------------------------------------------------------
// Best for the pendulum: the joint's error reduction at 1 (Bullet's default
// 0.2 lets the hinge drift and the correction feeds energy in and out) and
// 100 solver iterations instead of 10.
constexpr double BEST_JOINT_ERP = 1.0;
constexpr int BEST_ITERATIONS = 100;

class BulletPendulum : public PendulumModel {
 public:
  BulletPendulum(double bobMass, const RunOptions& options) : world_(SURFACE_GRAVITY), step_(options.step) {
    using namespace scene::test2;
    // ODE's attach(): one body, the rod and the sphere as children of a
    // compound shape placed around the composite centre of mass, with the
    // inertia about it worked out here (a compound's own estimate is a box's).
    const double mass = ROD_MASS + bobMass;
    const double centre = (ROD_MASS * ROD_LENGTH / 2 + bobMass * BOB_DISTANCE) / mass;
    const double bobOwn = 0.4 * bobMass * BOB_RADIUS * BOB_RADIUS;
    const double rodAlong = ROD_MASS * 2 * ROD_THICKNESS * ROD_THICKNESS / 12;
    const double rodAcross = ROD_MASS * (ROD_LENGTH * ROD_LENGTH + ROD_THICKNESS * ROD_THICKNESS) / 12 +
                             ROD_MASS * std::pow(ROD_LENGTH / 2 - centre, 2);
    const double across = rodAcross + bobOwn + bobMass * std::pow(BOB_DISTANCE - centre, 2);
    auto* compound = new btCompoundShape();
    auto* rod = new btBoxShape(btVector3(ROD_LENGTH / 2, ROD_THICKNESS / 2, ROD_THICKNESS / 2));
    auto* bob = new btSphereShape(BOB_RADIUS);
    btTransform at;
    at.setIdentity();
    at.setOrigin(btVector3(ROD_LENGTH / 2 - centre, 0, 0));
    compound->addChildShape(at, rod);
    at.setOrigin(btVector3(BOB_DISTANCE - centre, 0, 0));
    compound->addChildShape(at, bob);
    world_.add(new btStaticPlaneShape(btVector3(0, 1, 0), 0), 0.0, btVector3(0, 0, 0));
    body_ = world_.add(compound, mass, btVector3(centre, ANCHOR_HEIGHT, 0),
                       btVector3(rodAlong + bobOwn, across, across));
    // rod and bob are owned through the compound's children: keep them alive.
    keepChild_.emplace_back(rod);
    keepChild_.emplace_back(bob);
    auto* hinge = new btHingeConstraint(*body_, btVector3(-centre, 0, 0), btVector3(0, 0, 1));
    world_.keep(hinge);
    if (options.setting == Setting::Best) {
      world_.solverInfo().m_erp = BEST_JOINT_ERP;
      world_.solverInfo().m_numIterations = BEST_ITERATIONS;
    }
  }
  void step() override { world_.step(step_); }
  Vec3 centreOfMass() const override { return toVec3(body_->getCenterOfMassPosition()); }
  double kineticEnergy() const override {
    const btVector3 v = body_->getLinearVelocity();
    // Rotation in the body's principal frame, where Bullet keeps the inertia.
    const btVector3 w = body_->getCenterOfMassTransform().getBasis().transpose() * body_->getAngularVelocity();
    const btVector3 inertia = body_->getLocalInertia();
    return 0.5 * mass() * v.length2() +
           0.5 * (inertia.x() * w.x() * w.x() + inertia.y() * w.y() * w.y() + inertia.z() * w.z() * w.z());
  }
  double mass() const override { return 1.0 / body_->getInvMass(); }

 private:
  BulletWorld world_;
  double step_;
  btRigidBody* body_ = nullptr;
  std::vector<std::unique_ptr<btCollisionShape>> keepChild_;
};

// ---- test9 -------------------------------------------------------------------
// Best for the bounce: no speculative contacts (contact processing threshold
// 0 on both bodies), no positional correction of contacts (ERP 0, which also
// drops penetration recovery for every contact) and restitution at any impact
// speed (Bullet applies none below 0.2 m/s by default).
class BulletBall : public BallModel {
 public:
  explicit BulletBall(const RunOptions& options)
      : world_(scene::test9::GRAVITY_FACTOR * SURFACE_GRAVITY), step_(options.step) {
    using namespace scene::test9;
    btRigidBody* ground = world_.add(new btStaticPlaneShape(btVector3(0, 1, 0), 0), 0.0, btVector3(0, 0, 0));
    ball_ = world_.add(new btSphereShape(BALL_RADIUS), BALL_MASS, btVector3(0, START_HEIGHT, 0));
    // Restitution 1.0 on both: Bullet multiplies the two bodies' values.
    ground->setRestitution(BOUNCE);
    ball_->setRestitution(BOUNCE);
    if (options.setting == Setting::Best) {
      ground->setContactProcessingThreshold(0);
      ball_->setContactProcessingThreshold(0);
      world_.solverInfo().m_erp = 0;
      world_.solverInfo().m_erp2 = 0;
      world_.solverInfo().m_restitutionVelocityThreshold = 0;
    }
  }
  void step() override { world_.step(step_); }
  Vec3 centre() const override { return toVec3(ball_->getCenterOfMassPosition()); }

 private:
  BulletWorld world_;
  double step_;
  btRigidBody* ball_ = nullptr;
};

// ---- test4 -------------------------------------------------------------------
// Best for the stack: 100 solver iterations (the sequential-impulse solver
// converges slowly across a 1000:1 mass ratio).
class BulletStack : public StackModel {
 public:
  BulletStack(double bigMass, const RunOptions& options) : world_(SURFACE_GRAVITY), step_(options.step) {
    using namespace scene::test4;
    world_.add(new btBoxShape(btVector3(PLATFORM_SIDE / 2, PLATFORM_THICKNESS / 2, PLATFORM_SIDE / 2)), 0.0,
               btVector3(0, -PLATFORM_THICKNESS / 2, 0));
    world_.add(new btBoxShape(btVector3(SMALL_SIDE / 2, SMALL_SIDE / 2, SMALL_SIDE / 2)), SMALL_MASS,
               btVector3(0, SMALL_SIDE / 2, 0));
    big_ = world_.add(new btBoxShape(btVector3(BIG_SIDE / 2, BIG_SIDE / 2, BIG_SIDE / 2)), bigMass,
                      btVector3(0, BIG_START_HEIGHT, 0));
    if (options.setting == Setting::Best) world_.solverInfo().m_numIterations = BEST_ITERATIONS;
  }
  void step() override { world_.step(step_); }
  Vec3 bigCentre() const override { return toVec3(big_->getCenterOfMassPosition()); }
  double bigTiltDegrees() const override {
    const double up = big_->getCenterOfMassTransform().getBasis()[1][1];  // world y of the local y axis
    return std::acos(std::max(-1.0, std::min(1.0, up))) * 180.0 / M_PI;
  }
  double deepestPenetration() const override { return world_.deepestPenetration(); }

 private:
  mutable BulletWorld world_;
  double step_;
  btRigidBody* big_ = nullptr;
};

// ---- test10 ------------------------------------------------------------------
// Best for the wall, or --ccd: Bullet's continuous collision (100 solver
// iterations were measured to change nothing: 249 m/s at step 0.001 either way). A body moving more than the motion
// threshold in a step is swept as a sphere of the given radius (inside the
// cube: the inscribed sphere's radius is half the side) and stopped at the
// first hit, with a predictive contact made for the next solve.
constexpr double CCD_MOTION_THRESHOLD_FRACTION = 0.5;  // of the cube's half-size
constexpr double CCD_SWEPT_SPHERE_FRACTION = 0.9;      // of the cube's half-size

class BulletLaunch : public LaunchModel {
 public:
  BulletLaunch(double velocity, const RunOptions& options) : world_(SURFACE_GRAVITY), step_(options.step) {
    using namespace odelab::peers::test10;
    world_.add(new btStaticPlaneShape(btVector3(0, 1, 0), 0), 0.0, btVector3(0, 0, 0));
    world_.add(new btBoxShape(btVector3(WALL_THICKNESS / 2, WALL_HEIGHT / 2, WALL_WIDTH / 2)), 0.0,
               btVector3(WALL_X, WALL_HEIGHT / 2, 0));
    const double half = CUBE_SIDE / 2;
    cube_ = world_.add(new btBoxShape(btVector3(half, half, half)), CUBE_MASS, btVector3(LAUNCH_X, LAUNCH_Y, LAUNCH_Z));
    cube_->setLinearVelocity(btVector3(velocity, 0, 0));
    if (options.ccd || options.setting == Setting::Best) {  // CCD is what makes Bullet best here
      cube_->setCcdMotionThreshold(CCD_MOTION_THRESHOLD_FRACTION * half);
      cube_->setCcdSweptSphereRadius(CCD_SWEPT_SPHERE_FRACTION * half);
    }
  }
  void step() override { world_.step(step_); }
  Vec3 cubeCentre() const override { return toVec3(cube_->getCenterOfMassPosition()); }
  double cubeVelocityX() const override { return cube_->getLinearVelocity().x(); }

 private:
  BulletWorld world_;
  double step_;
  btRigidBody* cube_ = nullptr;
};

class Bullet : public EngineOf<BulletPendulum, BulletBall, BulletStack, BulletLaunch> {
 public:
  std::string name() const override { return "bullet"; }
  bool hasContinuousCollision() const override { return true; }
  std::string settingText(const RunOptions& o) const override {
    const bool best = o.setting == Setting::Best;
    std::string text = "btDiscreteDynamicsWorld, sequential impulse, stepSimulation(h, 0), sleeping off; ";
    if (o.scene == "test2" || o.scene == "test8")
      text += best ? "joint ERP 1.0, 100 iterations" : "joint ERP 0.2, 10 iterations (Bullet's defaults)";
    else if (o.scene == "test9")
      text += best ? "restitution 1.0 x 1.0, contact processing threshold 0, contact ERP 0, restitution at any speed"
                   : "restitution 1.0 x 1.0, otherwise Bullet's defaults (speculative contacts, ERP 0.2, "
                     "no restitution below 0.2 m/s)";
    else if (o.scene == "test4")
      text += best ? "100 iterations" : "Bullet's defaults (10 iterations, ERP 0.2, split impulse)";
    else
      text += best ? "continuous collision on" : "Bullet's defaults (no continuous collision)";
    if (o.ccd || (best && o.scene == "test10")) text += "; CCD: motion threshold 0.1 m, swept sphere radius 0.18 m";
    return text;
  }
};

}  // namespace

int main(int argc, char** argv) {
  Bullet bullet;
  return odelab::peers::runPeer(argc, argv, bullet);
}
