// bullet_lab: the thesis's measurement scenes on Bullet 3 (double precision,
// btDiscreteDynamicsWorld with its sequential-impulse solver), built with the
// same geometry, masses, gravity and step as the ODE programs. Settings per
// scene ("default" and "best") are named in settingText and doc/peers.md.
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <memory>
#include <vector>

#include "Measurements.h"
#include "PeerScene.h"
#include "Readouts.h"
#include "Test10Scene.h"
#include "Test3Scene.h"
#include "Test7Scene.h"
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

  // Bodies a constraint joins do not collide with each other, as in the
  // ODE programs (their near callback skips connected bodies).
  void keep(btTypedConstraint* constraint) {
    constraints_.emplace_back(constraint);
    world_.addConstraint(constraint, true);
  }

  // Fixed step, no substeps or interpolation (Bullet's default of
  // stepSimulation(h) would run 1/60 s substeps).
  void step(double h) { world_.stepSimulation(h, 0); }
  btContactSolverInfo& solverInfo() { return world_.getSolverInfo(); }
  // Bullet's exact bounce: no speculative contacts (contact processing
  // threshold 0 on every body), no positional correction of contacts (ERP 0,
  // which also drops penetration recovery for every contact) and restitution
  // at any impact speed (Bullet applies none below 0.2 m/s by default).
  void exactBounce() {
    for (int i = 0; i < world_.getNumCollisionObjects(); ++i)
      world_.getCollisionObjectArray()[i]->setContactProcessingThreshold(0);
    solverInfo().m_erp = 0;
    solverInfo().m_erp2 = 0;
    solverInfo().m_restitutionVelocityThreshold = 0;
  }
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
// Best for the bounce: Bullet's exact bounce (BulletWorld::exactBounce).
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
    if (options.setting == Setting::Best) world_.exactBounce();
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

// ---- test7 -------------------------------------------------------------------
// Best for the hanging pair: as the pendulum's, joint ERP 1.0 and 100 solver
// iterations (the 1000:1 mass ratio along the chain is what the sequential
// impulses converge slowly on).
class BulletHangingPair : public HangingPairModel {
 public:
  explicit BulletHangingPair(const RunOptions& options) : world_(SURFACE_GRAVITY), step_(options.step) {
    using namespace odelab::peers::test7;
    auto box = [](double side) { return new btBoxShape(btVector3(side / 2, side / 2, side / 2)); };
    world_.add(new btStaticPlaneShape(btVector3(0, 1, 0), 0), 0.0, btVector3(0, 0, 0));
    pivot_ = world_.add(box(PIVOT_SIDE), PIVOT_MASS, btVector3(0, PIVOT_CENTRE_Y, 0));
    big_ = world_.add(box(BIG_SIDE), BIG_MASS, btVector3(0, BIG_CENTRE_Y, 0));
    cube_ = world_.add(box(TEST_CUBE_SIDE), TEST_CUBE_MASS, btVector3(-THROW_DISTANCE, PIVOT_CENTRE_Y, 0));
    for (int i = 0; i < world_.world().getNumCollisionObjects(); ++i)
      world_.world().getCollisionObjectArray()[i]->setFriction(NO_SLIP_FRICTION);
    top_ = new btPoint2PointConstraint(*pivot_, pivotTop_);
    middle_ = new btPoint2PointConstraint(*pivot_, *big_, pivotBottom_, bigTop_);
    world_.keep(top_);
    world_.keep(middle_);
    if (options.setting == Setting::Best) {
      world_.solverInfo().m_erp = BEST_JOINT_ERP;
      world_.solverInfo().m_numIterations = BEST_ITERATIONS;
    }
    throwCube();
  }
  void step() override { world_.step(step_); }
  void throwCube() override {
    using namespace odelab::peers::test7;
    btTransform start;
    start.setIdentity();
    start.setOrigin(btVector3(-THROW_DISTANCE, PIVOT_CENTRE_Y, 0));
    cube_->setCenterOfMassTransform(start);
    cube_->getMotionState()->setWorldTransform(start);
    const double a = throwElevation();
    cube_->setLinearVelocity(btVector3(THROW_SPEED * std::cos(a), THROW_SPEED * std::sin(a), 0));
    cube_->setAngularVelocity(btVector3(0, 0, 0));
  }
  double jointError() const override {
    const btVector3 fixed(0, scene::test7::ANCHOR_HEIGHT, 0);
    const double top = (pivot_->getCenterOfMassTransform() * pivotTop_ - fixed).length();
    const double middle =
        (pivot_->getCenterOfMassTransform() * pivotBottom_ - big_->getCenterOfMassTransform() * bigTop_).length();
    return std::max(top, middle);
  }
  double pivotAngularSpeed() const override { return pivot_->getAngularVelocity().length(); }
  Vec3 pivotCentre() const override { return toVec3(pivot_->getCenterOfMassPosition()); }
  Vec3 testCubeCentre() const override { return toVec3(cube_->getCenterOfMassPosition()); }

 private:
  BulletWorld world_;
  double step_;
  btRigidBody *pivot_ = nullptr, *big_ = nullptr, *cube_ = nullptr;
  btTypedConstraint *top_ = nullptr, *middle_ = nullptr;
  // Each joint's anchor on each body, in the body's own frame.
  const btVector3 pivotTop_{0, scene::test7::PIVOT_SIDE / 2, 0}, pivotBottom_{0, -scene::test7::PIVOT_SIDE / 2, 0};
  const btVector3 bigTop_{0, scene::test7::BIG_SIDE / 2, 0};
};

// The world-y row of a body's rotation.
void upRow(const btRigidBody* body, double row[3]) {
  const btMatrix3x3& basis = body->getCenterOfMassTransform().getBasis();
  for (int i = 0; i < 3; ++i) row[i] = basis[1][i];
}

// ---- test1 -------------------------------------------------------------------
// Ball i with restitution i/49 over the ground's 1.0: Bullet multiplies the
// two, so each contact has the ball's own. Best: as test9's exact bounce (no
// speculative contacts, contact ERP 0, restitution at any impact speed).
class BulletBalls : public BallsModel {
 public:
  explicit BulletBalls(const RunOptions& options)
      : world_(scene::test1::GRAVITY_FACTOR * SURFACE_GRAVITY), step_(options.step) {
    using namespace scene::test1;
    world_.add(new btStaticPlaneShape(btVector3(0, 1, 0), 0), 0.0, btVector3(0, 0, 0))->setRestitution(1.0);
    for (int i = 0; i < BALL_COUNT; ++i) {
      const Vec3 start = ballStart(i);
      btRigidBody* ball = world_.add(new btSphereShape(BALL_RADIUS), BALL_MASS, btVector3(start.x, start.y, start.z));
      ball->setRestitution(ballBounce(i));
      balls_.push_back(ball);
    }
    if (options.setting == Setting::Best) world_.exactBounce();
  }
  void step() override { world_.step(step_); }
  int count() const override { return static_cast<int>(balls_.size()); }
  double bounce(int ball) const override { return balls_[ball]->getRestitution(); }
  Vec3 centre(int ball) const override { return toVec3(balls_[ball]->getCenterOfMassPosition()); }
  double speed(int ball) const override { return balls_[ball]->getLinearVelocity().length(); }
  double bounceVelocity() const override { return world_.solverInfo().m_restitutionVelocityThreshold; }

 private:
  mutable BulletWorld world_;
  double step_;
  std::vector<btRigidBody*> balls_;
};

// ---- test6 -------------------------------------------------------------------
// The big cube on a btPoint2PointConstraint 2 m above the small cube's top
// (the two do not collide with each other), friction 100 on every shape
// (test6's never-sliding contacts). Best: 100 iterations.
class BulletUpright : public UprightModel {
 public:
  explicit BulletUpright(const RunOptions& options) : world_(SURFACE_GRAVITY), step_(options.step) {
    using namespace scene::test6;
    auto box = [](double side) { return new btBoxShape(btVector3(side / 2, side / 2, side / 2)); };
    world_.add(new btStaticPlaneShape(btVector3(0, 1, 0), 0), 0.0, btVector3(0, 0, 0));
    small_ = world_.add(box(SMALL_SIDE), SMALL_MASS, btVector3(0, SMALL_SIDE / 2, 0));
    big_ = world_.add(box(BIG_SIDE), BIG_MASS, btVector3(0, ANCHOR_HEIGHT + BIG_SIDE / 2, 0));
    for (int i = 0; i < world_.world().getNumCollisionObjects(); ++i)
      world_.world().getCollisionObjectArray()[i]->setFriction(NO_SLIP_FRICTION);
    world_.keep(new btPoint2PointConstraint(*small_, *big_, btVector3(0, ANCHOR_HEIGHT - SMALL_SIDE / 2, 0),
                                            btVector3(0, -BIG_SIDE / 2, 0)));
    if (options.setting == Setting::Best) world_.solverInfo().m_numIterations = BEST_ITERATIONS;
  }
  void step() override { world_.step(step_); }
  Vec3 bigCentre() const override { return toVec3(big_->getCenterOfMassPosition()); }
  double bigTiltDegrees() const override {
    double row[3];
    upRow(big_, row);
    return tiltDegrees(row);
  }
  double smallSink() const override {
    double row[3];
    upRow(small_, row);
    return depthBelowGround(toVec3(small_->getCenterOfMassPosition()), row, scene::test6::SMALL_SIDE);
  }

 private:
  BulletWorld world_;
  double step_;
  btRigidBody *small_ = nullptr, *big_ = nullptr;
};

// ---- test3 -------------------------------------------------------------------
// The dominoes with friction 1.0 (Bullet multiplies: 1.0) and, as test3's
// auto-disable, sleeping on with the thesis's thresholds (0.1 m/s, 0.1 rad/s;
// Bullet's own are 0.8 and 1.0) after Bullet's 2 s below them (ODE: 10
// steps). Best: 100 iterations.
class BulletDominoes : public DominoModel {
 public:
  explicit BulletDominoes(const RunOptions& options) : world_(SURFACE_GRAVITY), step_(options.step) {
    using namespace odelab::peers::test3;
    world_.add(new btStaticPlaneShape(btVector3(0, 1, 0), 0), 0.0, btVector3(0, 0, 0))->setFriction(DEFAULT_MU);
    for (const DominoStart& d : dominoStarts(DEFAULT_DOMINOES)) {
      btRigidBody* domino =
          world_.add(new btBoxShape(btVector3(DOMINO_THICKNESS / 2, DOMINO_HEIGHT / 2, DOMINO_WIDTH / 2)), DOMINO_MASS,
                     btVector3(d.centre.x, d.centre.y, d.centre.z));
      btTransform pose(btQuaternion(d.quaternion[1], d.quaternion[2], d.quaternion[3], d.quaternion[0]),
                       btVector3(d.centre.x, d.centre.y, d.centre.z));
      domino->setCenterOfMassTransform(pose);
      domino->getMotionState()->setWorldTransform(pose);
      domino->setLinearVelocity(btVector3(d.velocity.x, d.velocity.y, d.velocity.z));
      domino->setAngularVelocity(btVector3(d.spin.x, d.spin.y, d.spin.z));
      domino->setFriction(DEFAULT_MU);
      domino->forceActivationState(ACTIVE_TAG);
      domino->setSleepingThresholds(AUTO_DISABLE_THRESHOLD, AUTO_DISABLE_THRESHOLD);
      dominoes_.push_back(domino);
    }
    if (options.setting == Setting::Best) world_.solverInfo().m_numIterations = BEST_ITERATIONS;
  }
  void step() override { world_.step(step_); }
  int count() const override { return static_cast<int>(dominoes_.size()); }
  double tiltDegrees(int domino) const override {
    double row[3];
    upRow(dominoes_[domino], row);
    return odelab::peers::tiltDegrees(row);
  }
  int activeBodies() const override {
    int active = 0;
    for (const btRigidBody* d : dominoes_) active += d->isActive();
    return active;
  }
  bool sleeps() const override { return true; }

 private:
  BulletWorld world_;
  double step_;
  std::vector<btRigidBody*> dominoes_;
};

// ---- test5 -------------------------------------------------------------------
// Plates on the platform, friction 100 (test5's never-sliding contacts; ODE's
// mu dInfinity), sleeping off as in every scene but test3. Best: 100 iterations.
class BulletPlates : public PlateStackModel {
 public:
  explicit BulletPlates(const RunOptions& options) : world_(SURFACE_GRAVITY), step_(options.step) {
    using namespace scene::test5;
    world_.add(new btBoxShape(btVector3(PLATFORM_SIDE / 2, PLATFORM_THICKNESS / 2, PLATFORM_SIDE / 2)), 0.0,
               btVector3(0, -PLATFORM_THICKNESS / 2, 0))
        ->setFriction(NO_SLIP_FRICTION);
    if (options.setting == Setting::Best) world_.solverInfo().m_numIterations = BEST_ITERATIONS;
  }
  void step() override { world_.step(step_); }
  void dropPlate(double height) override {
    using namespace scene::test5;
    btRigidBody* plate = world_.add(new btBoxShape(btVector3(PLATE_WIDTH / 2, PLATE_THICKNESS / 2, PLATE_WIDTH / 2)),
                                    PLATE_MASS, btVector3(0, height, 0));
    plate->setFriction(NO_SLIP_FRICTION);
    plates_.push_back(plate);
  }
  int count() const override { return static_cast<int>(plates_.size()); }
  Vec3 plateCentre(int plate) const override { return toVec3(plates_[plate]->getCenterOfMassPosition()); }
  double plateSpeed(int plate) const override { return plates_[plate]->getLinearVelocity().length(); }
  double plateYawDegrees(int plate) const override {
    const btMatrix3x3& r = plates_[plate]->getCenterOfMassTransform().getBasis();  // local x in world: column 0
    return std::atan2(-r[2][0], r[0][0]) * 180.0 / M_PI;
  }

 private:
  BulletWorld world_;
  double step_;
  std::vector<btRigidBody*> plates_;
};

class Bullet : public EngineOf<BulletPendulum, BulletBall, BulletStack, BulletLaunch, BulletHangingPair, BulletBalls,
                               BulletUpright, BulletDominoes, BulletPlates> {
 public:
  std::string name() const override { return "bullet"; }
  std::string version() const override {  // btGetVersion(): 324 for 3.24
    const int v = btGetVersion();
    return std::to_string(v / 100) + "." + std::to_string(v % 100);
  }
  bool hasContinuousCollision() const override { return true; }
  std::string settingText(const RunOptions& o) const override {
    const bool best = o.setting == Setting::Best;
    std::string text = "btDiscreteDynamicsWorld, sequential impulse, stepSimulation(h, 0)";
    text += o.scene == "test3" ? "; " : ", sleeping off; ";
    if (o.scene == "test2" || o.scene == "test8")
      text += best ? "joint ERP 1.0, 100 iterations" : "joint ERP 0.2, 10 iterations (Bullet's defaults)";
    else if (o.scene == "test9")
      text += best ? "restitution 1.0 x 1.0, contact processing threshold 0, contact ERP 0, restitution at any speed"
                   : "restitution 1.0 x 1.0, otherwise Bullet's defaults (speculative contacts, ERP 0.2, "
                     "no restitution below 0.2 m/s)";
    else if (o.scene == "test4")
      text += best ? "100 iterations" : "Bullet's defaults (10 iterations, ERP 0.2, split impulse)";
    else if (o.scene == "test1")
      text += best ? "each ball's restitution x the ground's 1.0, contact processing threshold 0, contact ERP 0, "
                     "restitution at any speed"
                   : "each ball's restitution x the ground's 1.0, otherwise Bullet's defaults (speculative contacts, "
                     "ERP 0.2, no restitution below 0.2 m/s)";
    else if (o.scene == "test6")
      text += std::string(best ? "100 iterations" : "Bullet's defaults (10 iterations, ERP 0.2)") +
              "; btPoint2PointConstraint ball joint, friction 100 on every shape (test6's never-sliding contacts)";
    else if (o.scene == "test5")
      text += std::string(best ? "100 iterations" : "Bullet's defaults (10 iterations)") +
              "; friction 100 on every shape (test5's never-sliding contacts)";
    else if (o.scene == "test3")
      text += std::string(best ? "100 iterations" : "Bullet's defaults (10 iterations)") +
              "; friction 1.0, sleeping on with thresholds 0.1 m/s and 0.1 rad/s after Bullet's 2 s";
    else if (o.scene == "test7")
      text += std::string(best ? "joint ERP 1.0, 100 iterations" : "joint ERP 0.2, 10 iterations (Bullet's defaults)") +
              "; btPoint2PointConstraint ball joints, friction 100 on every shape (test7's never-sliding contacts), "
              "no angular speed cap";
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
