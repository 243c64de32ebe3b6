// mujoco_lab: the thesis's measurement scenes on MuJoCo 2 (generalized
// coordinates, soft contacts), each scene an MJCF text generated here and
// loaded from memory through a virtual file system: no files beside the
// binary. Same geometry, masses, gravity and step as the ODE programs;
// MuJoCo's z-up habit is kept out of the way by pointing gravity along -y and
// turning the ground plane's normal (its local z) to +y.
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <cstring>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

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

constexpr char MODEL_FILE[] = "scene.xml";

// Best for the bounce: MuJoCo has no restitution coefficient; its documented
// way to a bouncy contact is a negative solref, "-stiffness -damping", here
// with zero damping (an undamped spring contact), integrated with RK4. The
// stiffness is the contact's acceleration per metre of overlap: 5e3 /s^2
// lasts pi / sqrt(5e3) = 44 ms (44 steps at 0.001 s) and sinks the ball
// 0.27 m at the scene's 18.8 m/s impact. Stiffer springs (2e4, 1e5) were
// measured less accurate at step 0.001 (apex error after 20 bounces 5e-3 and
// 8e-3 against 1.7e-4): fewer steps per contact.
constexpr double BOUNCE_STIFFNESS = 5e3;

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

// Loads MJCF text through a virtual file (the VFS is about 2 MB: on the heap).
mjModel* loadModel(const std::string& xml) {
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), MODEL_FILE, static_cast<int>(xml.size())) != 0)
    throw std::runtime_error("MuJoCo: cannot make the virtual model file");
  const int index = mj_findFileVFS(vfs.get(), MODEL_FILE);
  std::memcpy(vfs->filedata[index], xml.data(), xml.size());
  char error[1000] = "";
  mjModel* model = mj_loadXML(MODEL_FILE, vfs.get(), error, sizeof error);
  mj_deleteVFS(vfs.get());
  if (!model) throw std::runtime_error(std::string("MuJoCo rejected the generated model: ") + error);
  return model;
}

// A loaded scene: the model, its data, and the fixed step.
class MujocoScene {
 public:
  explicit MujocoScene(const std::string& xml) : model_(loadModel(xml)), data_(mj_makeData(model_.get())) {
    mj_forward(model_.get(), data_.get());
  }
  void step() {
    mj_step(model_.get(), data_.get());
    // MuJoCo answers a NaN, infinite or huge acceleration by resetting the
    // state and going on: a result measured after that would be a lie.
    if (data_->warning[mjWARN_BADQACC].number > 0)
      throw std::runtime_error("MuJoCo found a bad acceleration (NaN, infinite or huge) at t=" +
                               std::to_string(data_->time) + " s and reset the simulation; no result");
  }
  mjModel* m() const { return model_.get(); }
  mjData* d() const { return data_.get(); }

 private:
  std::unique_ptr<mjModel, ModelDeleter> model_;
  std::unique_ptr<mjData, DataDeleter> data_;
};

// The <mujoco> header every scene shares: step, gravity along -y, integrator.
std::string header(const char* name, double step, double gravity, const char* integrator,
                   const std::string& extraOptions = "") {
  std::ostringstream s;
  s.precision(17);
  s << "<mujoco model=\"" << name << "\">\n"
    << "  <compiler angle=\"radian\"/>\n"
    << "  <option timestep=\"" << step << "\" gravity=\"0 " << -gravity << " 0\" integrator=\"" << integrator
    << "\" " << extraOptions << "/>\n";
  return s.str();
}

const char* GROUND = "    <geom name=\"ground\" type=\"plane\" size=\"0 0 1\" zaxis=\"0 1 0\"/>\n";

// ---- test2 / test8 ---------------------------------------------------------------
// Best for the pendulum: RK4 instead of MuJoCo's default semi-implicit Euler.
class Mujoco;

class MujocoPendulum : public PendulumModel {
  friend class Mujoco;  // its model text, for --write-model

 public:
  MujocoPendulum(double bobMass, const RunOptions& o) : scene_(xml(bobMass, o)) {
    // One hinge to the world: the joint-space inertia is the body's moment
    // about the axis, the same in every pose.
    axisInertia_ = scene_.d()->qM[0];
  }
  void step() override {
    scene_.step();
    mj_kinematics(scene_.m(), scene_.d());  // positions of the new state (mj_step leaves the old ones)
  }
  Vec3 centreOfMass() const override {
    const double* c = scene_.d()->xipos + 3;  // body 1
    return {c[0], c[1], c[2]};
  }
  double kineticEnergy() const override { return 0.5 * axisInertia_ * scene_.d()->qvel[0] * scene_.d()->qvel[0]; }
  double mass() const override { return scene_.m()->body_mass[1]; }

 private:
  static std::string xml(double bobMass, const RunOptions& o) {
    using namespace scene::test2;
    std::ostringstream s;
    s.precision(17);
    s << header("odelab-pendulum", o.step, SURFACE_GRAVITY, o.setting == Setting::Best ? "RK4" : "Euler")
      << "  <worldbody>\n" << GROUND
      << "    <body pos=\"0 " << ANCHOR_HEIGHT << " 0\">\n"
      << "      <joint type=\"hinge\" axis=\"0 0 1\" pos=\"0 0 0\"/>\n"
      << "      <geom type=\"box\" pos=\"" << ROD_LENGTH / 2 << " 0 0\" size=\"" << ROD_LENGTH / 2 << ' '
      << ROD_THICKNESS / 2 << ' ' << ROD_THICKNESS / 2 << "\" mass=\"" << ROD_MASS << "\"/>\n"
      << "      <geom type=\"sphere\" pos=\"" << BOB_DISTANCE << " 0 0\" size=\"" << BOB_RADIUS << "\" mass=\""
      << bobMass << "\"/>\n"
      << "    </body>\n  </worldbody>\n</mujoco>\n";
    return s.str();
  }
  MujocoScene scene_;
  double axisInertia_ = 0.0;
};

// ---- test9 -------------------------------------------------------------------
class MujocoBall : public BallModel {
  friend class Mujoco;

 public:
  explicit MujocoBall(const RunOptions& o) : scene_(xml(o)) {}
  void step() override { scene_.step(); }
  Vec3 centre() const override {
    const double* q = scene_.d()->qpos;  // free joint: position first
    return {q[0], q[1], q[2]};
  }

 private:
  static std::string xml(const RunOptions& o) {
    using namespace scene::test9;
    const bool best = o.setting == Setting::Best;
    std::ostringstream s;
    s.precision(17);
    s << header("odelab-test9", o.step, GRAVITY_FACTOR * SURFACE_GRAVITY, best ? "RK4" : "Euler")
      << "  <worldbody>\n" << GROUND
      << "    <body pos=\"0 " << START_HEIGHT << " 0\">\n      <freejoint/>\n"
      << "      <geom type=\"sphere\" size=\"" << BALL_RADIUS << "\" mass=\"" << BALL_MASS << "\"";
    if (best) s << " solref=\"" << -BOUNCE_STIFFNESS << " 0\"";
    s << "/>\n    </body>\n  </worldbody>\n</mujoco>\n";
    return s.str();
  }
  MujocoScene scene_;
};

// ---- test4 -------------------------------------------------------------------
// Best for the stack: the stiffest contacts MuJoCo accepts at this step (time
// constant 2 steps, its safe minimum, instead of 0.02 s), impedance near 1
// (a harder contact: less of the load is let through as overlap) and
// elliptic friction cones.
const char* BEST_SOLIMP = "0.99 0.999 0.001";
class MujocoStack : public StackModel {
 public:
  MujocoStack(double bigMass, const RunOptions& o) : scene_(xml(bigMass, o)) {}
  void step() override { scene_.step(); }
  Vec3 bigCentre() const override {
    const double* q = scene_.d()->qpos + 7;  // second free joint: the big cube
    return {q[0], q[1], q[2]};
  }
  double bigTiltDegrees() const override {
    const double* q = scene_.d()->qpos + 10;  // its quaternion w, x, y, z
    const double up = 1 - 2 * (q[1] * q[1] + q[3] * q[3]);  // world y of the local y axis
    return std::acos(std::max(-1.0, std::min(1.0, up))) * 180.0 / M_PI;
  }
  double deepestPenetration() const override {
    double deepest = 0.0;
    for (int i = 0; i < scene_.d()->ncon; ++i) deepest = std::max(deepest, -scene_.d()->contact[i].dist);
    return deepest;
  }

 private:
  static std::string xml(double bigMass, const RunOptions& o) {
    using namespace scene::test4;
    const bool best = o.setting == Setting::Best;
    std::ostringstream s;
    s.precision(17);
    s << header("odelab-test4", o.step, SURFACE_GRAVITY, "Euler", best ? "cone=\"elliptic\"" : "");
    if (best) s << "  <default><geom solref=\"" << 2 * o.step << " 1\" solimp=\"" << BEST_SOLIMP << "\"/></default>\n";
    s << "  <worldbody>\n"
      << "    <geom type=\"box\" pos=\"0 " << -PLATFORM_THICKNESS / 2 << " 0\" size=\"" << PLATFORM_SIDE / 2 << ' '
      << PLATFORM_THICKNESS / 2 << ' ' << PLATFORM_SIDE / 2 << "\"/>\n"
      << "    <body pos=\"0 " << SMALL_SIDE / 2 << " 0\">\n      <freejoint/>\n"
      << "      <geom type=\"box\" size=\"" << SMALL_SIDE / 2 << ' ' << SMALL_SIDE / 2 << ' ' << SMALL_SIDE / 2
      << "\" mass=\"" << SMALL_MASS << "\"/>\n    </body>\n"
      << "    <body pos=\"0 " << BIG_START_HEIGHT << " 0\">\n      <freejoint/>\n"
      << "      <geom type=\"box\" size=\"" << BIG_SIDE / 2 << ' ' << BIG_SIDE / 2 << ' ' << BIG_SIDE / 2
      << "\" mass=\"" << bigMass << "\"/>\n    </body>\n"
      << "  </worldbody>\n</mujoco>\n";
    return s.str();
  }
  MujocoScene scene_;
};

// ---- test10 ------------------------------------------------------------------
// Best for the wall: the stiffest contact MuJoCo accepts at this step (time
// constant 2 steps, its safe minimum; the default is 0.02 s), so that a cube
// sinks less far into the wall before it is pushed back.
class MujocoLaunch : public LaunchModel {
 public:
  MujocoLaunch(double velocity, const RunOptions& o) : scene_(xml(o)) {
    scene_.d()->qvel[0] = velocity;
    mj_forward(scene_.m(), scene_.d());
  }
  void step() override { scene_.step(); }
  Vec3 cubeCentre() const override {
    const double* q = scene_.d()->qpos;
    return {q[0], q[1], q[2]};
  }
  double cubeVelocityX() const override { return scene_.d()->qvel[0]; }

 private:
  static std::string xml(const RunOptions& o) {
    using namespace odelab::peers::test10;
    const bool best = o.setting == Setting::Best;
    std::ostringstream s;
    s.precision(17);
    s << header("odelab-test10", o.step, SURFACE_GRAVITY, "Euler");
    if (best) s << "  <default><geom solref=\"" << 2 * o.step << " 1\"/></default>\n";
    s << "  <worldbody>\n" << GROUND
      << "    <geom type=\"box\" pos=\"" << WALL_X << ' ' << WALL_HEIGHT / 2 << " 0\" size=\"" << WALL_THICKNESS / 2
      << ' ' << WALL_HEIGHT / 2 << ' ' << WALL_WIDTH / 2 << "\"/>\n"
      << "    <body pos=\"" << LAUNCH_X << ' ' << LAUNCH_Y << ' ' << LAUNCH_Z << "\">\n      <freejoint/>\n"
      << "      <geom type=\"box\" size=\"" << CUBE_SIDE / 2 << ' ' << CUBE_SIDE / 2 << ' ' << CUBE_SIDE / 2
      << "\" mass=\"" << CUBE_MASS << "\"/>\n    </body>\n"
      << "  </worldbody>\n</mujoco>\n";
    return s.str();
  }
  MujocoScene scene_;
};

// ---- test7 -------------------------------------------------------------------
// The pair is a chain of bodies in generalized coordinates: the pivot on a
// ball joint to the world, the big cube on a ball joint to the pivot; the
// joints cannot come apart, so their error is the rounding of the forward
// kinematics. Best: as test4's, the stiffest contact at this step and
// elliptic cones (the hit is a contact).
class MujocoHangingPair : public HangingPairModel {
 public:
  explicit MujocoHangingPair(const RunOptions& o) : scene_(xml(o)) { throwCube(); }
  void step() override {
    scene_.step();
    mj_kinematics(scene_.m(), scene_.d());  // the new state's poses (mj_step leaves the old ones)
  }
  void throwCube() override {
    using namespace odelab::peers::test7;
    double* q = scene_.d()->qpos + CUBE_QPOS;  // free joint: position, then quaternion w, x, y, z
    const double position[7] = {-THROW_DISTANCE, PIVOT_CENTRE_Y, 0, 1, 0, 0, 0};
    std::copy(position, position + 7, q);
    double* v = scene_.d()->qvel + CUBE_QVEL;
    const double a = throwElevation();
    const double velocity[6] = {THROW_SPEED * std::cos(a), THROW_SPEED * std::sin(a), 0, 0, 0, 0};
    std::copy(velocity, velocity + 6, v);
    mj_kinematics(scene_.m(), scene_.d());
  }
  double jointError() const override {
    using namespace odelab::scene::test7;
    const Vec3 fixed{0, ANCHOR_HEIGHT, 0};
    const double top = distanceBetween(pointOn(PIVOT, PIVOT_SIDE / 2), fixed);
    const double middle = distanceBetween(pointOn(PIVOT, -PIVOT_SIDE / 2), pointOn(BIG, BIG_SIDE / 2));
    return std::max(top, middle);
  }
  double pivotAngularSpeed() const override {
    const double* w = scene_.d()->qvel;  // the pivot's ball joint: its angular velocity (in its own axes)
    return std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  }
  Vec3 pivotCentre() const override { return pointOn(PIVOT, 0); }
  Vec3 testCubeCentre() const override {
    const double* q = scene_.d()->qpos + CUBE_QPOS;
    return {q[0], q[1], q[2]};
  }

 private:
  static constexpr int PIVOT = 1, BIG = 2;            // bodies, in the order of the MJCF
  static constexpr int CUBE_QPOS = 8, CUBE_QVEL = 6;  // after the two ball joints (4 + 4 and 3 + 3)
  // The point at height `y` on a body's local y axis, in world coordinates.
  Vec3 pointOn(int body, double y) const {
    const double* p = scene_.d()->xpos + 3 * body;
    const double* r = scene_.d()->xmat + 9 * body;  // row-major
    return {p[0] + r[1] * y, p[1] + r[4] * y, p[2] + r[7] * y};
  }
  static double distanceBetween(const Vec3& a, const Vec3& b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z); }
  static std::string xml(const RunOptions& o) {
    using namespace odelab::peers::test7;
    const bool best = o.setting == Setting::Best;
    auto box = [](double side, double mass) {
      std::ostringstream g;
      g.precision(17);
      g << "<geom type=\"box\" size=\"" << side / 2 << ' ' << side / 2 << ' ' << side / 2 << "\" mass=\"" << mass
        << "\"/>";
      return g.str();
    };
    std::ostringstream s;
    s.precision(17);
    s << header("odelab-test7", o.step, SURFACE_GRAVITY, "Euler", best ? "cone=\"elliptic\"" : "")
      << "  <default><geom friction=\"" << NO_SLIP_FRICTION << " 0.005 0.0001\"";
    if (best) s << " solref=\"" << 2 * o.step << " 1\"";
    s << "/></default>\n  <worldbody>\n" << GROUND
      << "    <body pos=\"0 " << PIVOT_CENTRE_Y << " 0\">\n"
      << "      <joint type=\"ball\" pos=\"0 " << PIVOT_SIDE / 2 << " 0\"/>\n      " << box(PIVOT_SIDE, PIVOT_MASS) << '\n'
      << "      <body pos=\"0 " << BIG_CENTRE_Y - PIVOT_CENTRE_Y << " 0\">\n"
      << "        <joint type=\"ball\" pos=\"0 " << BIG_SIDE / 2 << " 0\"/>\n        " << box(BIG_SIDE, BIG_MASS) << '\n'
      << "      </body>\n    </body>\n"
      << "    <body pos=\"" << -THROW_DISTANCE << ' ' << PIVOT_CENTRE_Y << " 0\">\n      <freejoint/>\n      "
      << box(TEST_CUBE_SIDE, TEST_CUBE_MASS) << "\n    </body>\n"
      << "  </worldbody>\n</mujoco>\n";
    return s.str();
  }
  MujocoScene scene_;
};

// A body's centre and the world-y row of its rotation (xmat is row-major).
Vec3 centreOf(const mjData* d, int body) { return {d->xpos[3 * body], d->xpos[3 * body + 1], d->xpos[3 * body + 2]}; }
const double* upRowOf(const mjData* d, int body) { return d->xmat + 9 * body + 3; }

// ---- test1 -------------------------------------------------------------------
// MuJoCo has no restitution coefficient. Default: its own contact, the same
// for every ball (critically damped: no ball bounces). Best: each ball's
// contact a spring with damping, solref "-k -b" (as test9's spring, k =
// 5e3 /s^2, integrated with RK4), the damping chosen so that a free linear
// spring-damper gives back e of the impact speed: damping ratio
// z = -ln e / sqrt(pi^2 + ln^2 e), b = 2 z sqrt(k); e = 0 is critical damping.
class MujocoBalls : public BallsModel {
 public:
  explicit MujocoBalls(const RunOptions& o) : best_(o.setting == Setting::Best), scene_(xml(o)) {}
  void step() override {
    scene_.step();
    mj_kinematics(scene_.m(), scene_.d());
  }
  int count() const override { return scene::test1::BALL_COUNT; }
  double bounce(int ball) const override { return ballBounce(ball); }
  Vec3 centre(int ball) const override { return centreOf(scene_.d(), ball + 1); }
  double speed(int ball) const override {
    const double* v = scene_.d()->qvel + 6 * ball;  // free joint: linear velocity first
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  }
  double bounceVelocity() const override { return best_ ? 0.0 : std::nan(""); }

 private:
  static double damping(double e) {
    if (e <= 0) return 2 * std::sqrt(BOUNCE_STIFFNESS);
    const double l = std::log(e);
    return 2 * (-l / std::sqrt(M_PI * M_PI + l * l)) * std::sqrt(BOUNCE_STIFFNESS);
  }
  static std::string xml(const RunOptions& o) {
    using namespace scene::test1;
    const bool best = o.setting == Setting::Best;
    std::ostringstream s;
    s.precision(17);
    s << header("odelab-test1", o.step, GRAVITY_FACTOR * SURFACE_GRAVITY, best ? "RK4" : "Euler")
      << "  <worldbody>\n" << GROUND;
    for (int i = 0; i < BALL_COUNT; ++i) {
      const Vec3 p = ballStart(i);
      s << "    <body pos=\"" << p.x << ' ' << p.y << ' ' << p.z << "\">\n      <freejoint/>\n"
        << "      <geom type=\"sphere\" size=\"" << BALL_RADIUS << "\" mass=\"" << BALL_MASS << "\"";
      if (best) s << " solref=\"" << -BOUNCE_STIFFNESS << ' ' << -damping(ballBounce(i)) << "\"";
      s << "/>\n    </body>\n";
    }
    s << "  </worldbody>\n</mujoco>\n";
    return s.str();
  }
  bool best_;
  MujocoScene scene_;
};

// ---- test6 -------------------------------------------------------------------
// The small cube free on the ground, the big cube its child on a ball joint
// 2 m above its top (generalized coordinates: the joint cannot come apart),
// friction 100 (test6's never-sliding contacts). Best: as test4's, the
// stiffest contact at this step and elliptic cones.
class MujocoUpright : public UprightModel {
 public:
  explicit MujocoUpright(const RunOptions& o) : scene_(xml(o)) {}
  void step() override {
    scene_.step();
    mj_kinematics(scene_.m(), scene_.d());
  }
  Vec3 bigCentre() const override { return centreOf(scene_.d(), BIG); }
  double bigTiltDegrees() const override { return tiltDegrees(upRowOf(scene_.d(), BIG)); }
  double smallSink() const override {
    return depthBelowGround(centreOf(scene_.d(), SMALL), upRowOf(scene_.d(), SMALL), scene::test6::SMALL_SIDE);
  }

 private:
  static constexpr int SMALL = 1, BIG = 2;  // bodies, in the order of the MJCF
  static std::string xml(const RunOptions& o) {
    using namespace scene::test6;
    const bool best = o.setting == Setting::Best;
    std::ostringstream s;
    s.precision(17);
    s << header("odelab-test6", o.step, SURFACE_GRAVITY, "Euler", best ? "cone=\"elliptic\"" : "")
      << "  <default><geom friction=\"" << NO_SLIP_FRICTION << " 0.005 0.0001\"";
    if (best) s << " solref=\"" << 2 * o.step << " 1\" solimp=\"" << BEST_SOLIMP << "\"";
    s << "/></default>\n  <worldbody>\n" << GROUND
      << "    <body pos=\"0 " << SMALL_SIDE / 2 << " 0\">\n      <freejoint/>\n"
      << "      <geom type=\"box\" size=\"" << SMALL_SIDE / 2 << ' ' << SMALL_SIDE / 2 << ' ' << SMALL_SIDE / 2
      << "\" mass=\"" << SMALL_MASS << "\"/>\n"
      << "      <body pos=\"0 " << ANCHOR_HEIGHT + BIG_SIDE / 2 - SMALL_SIDE / 2 << " 0\">\n"
      << "        <joint type=\"ball\" pos=\"0 " << -BIG_SIDE / 2 << " 0\"/>\n"
      << "        <geom type=\"box\" size=\"" << BIG_SIDE / 2 << ' ' << BIG_SIDE / 2 << ' ' << BIG_SIDE / 2
      << "\" mass=\"" << BIG_MASS << "\"/>\n      </body>\n    </body>\n"
      << "  </worldbody>\n</mujoco>\n";
    return s.str();
  }
  MujocoScene scene_;
};

// ---- test3 -------------------------------------------------------------------
// The dominoes with friction 1.0. MuJoCo 2.2 has no sleeping: every body is
// stepped to the end (test3's auto-disable has nothing to map to). Best: as
// test4's, the stiffest contact at this step and elliptic cones.
class MujocoDominoes : public DominoModel {
  static constexpr int CONTACTS = 500;

 public:
  explicit MujocoDominoes(const RunOptions& o) : scene_(xml(o)) {
    const auto first = test3::dominoStarts(1).front();
    const double velocity[6] = {first.velocity.x, first.velocity.y, first.velocity.z,
                                first.spin.x,     first.spin.y,     first.spin.z};
    std::copy(velocity, velocity + 6, scene_.d()->qvel);  // free joint: linear, then angular (world axes)
    mj_forward(scene_.m(), scene_.d());
  }
  void step() override {
    scene_.step();
    mj_kinematics(scene_.m(), scene_.d());
  }
  int count() const override { return scene::test3::DEFAULT_DOMINOES; }
  double tiltDegrees(int domino) const override { return odelab::peers::tiltDegrees(upRowOf(scene_.d(), domino + 1)); }
  int activeBodies() const override { return count(); }
  bool sleeps() const override { return false; }

 private:
  static std::string xml(const RunOptions& o) {
    using namespace odelab::peers::test3;
    const bool best = o.setting == Setting::Best;
    std::ostringstream s;
    s.precision(17);
    // MuJoCo 2.2 holds 100 contacts by default: sixty plates leaning on each
    // other need more (and four constraint rows a contact in a pyramidal cone).
    s << header("odelab-test3", o.step, SURFACE_GRAVITY, "Euler", best ? "cone=\"elliptic\"" : "")
      << "  <size nconmax=\"" << CONTACTS << "\" njmax=\"" << 4 * CONTACTS << "\"/>\n"
      << "  <default><geom friction=\"" << DEFAULT_MU << " 0.005 0.0001\"";
    if (best) s << " solref=\"" << 2 * o.step << " 1\" solimp=\"" << BEST_SOLIMP << "\"";
    s << "/></default>\n  <worldbody>\n" << GROUND;
    for (const DominoStart& d : dominoStarts(DEFAULT_DOMINOES))
      s << "    <body pos=\"" << d.centre.x << ' ' << d.centre.y << ' ' << d.centre.z << "\" quat=\"" << d.quaternion[0]
        << ' ' << d.quaternion[1] << ' ' << d.quaternion[2] << ' ' << d.quaternion[3] << "\">\n      <freejoint/>\n"
        << "      <geom type=\"box\" size=\"" << DOMINO_THICKNESS / 2 << ' ' << DOMINO_HEIGHT / 2 << ' '
        << DOMINO_WIDTH / 2 << "\" mass=\"" << DOMINO_MASS << "\"/>\n    </body>\n";
    s << "  </worldbody>\n</mujoco>\n";
    return s.str();
  }
  MujocoScene scene_;
};

// ---- test5 -------------------------------------------------------------------
// MuJoCo 2.2 cannot add a body to a built model: the model holds every plate
// from the start, parked far apart out of the way (each on its own spot
// 1 km below the platform, put back there at rest after every step until
// dropped), and a plate is dropped by moving it over the platform. Friction 100 (test5's never-sliding contacts). Best: as test4's.
class MujocoPlates : public PlateStackModel {
 public:
  explicit MujocoPlates(const RunOptions& o)
      : plates_(o.plates > 0 ? o.plates : scene::test5::DEFAULT_PLATES), scene_(xml(o, plates_)) {}
  void step() override {
    scene_.step();
    for (int i = dropped_; i < plates_; ++i) park(i);
    mj_kinematics(scene_.m(), scene_.d());
  }
  void dropPlate(double height) override {
    double* q = scene_.d()->qpos + 7 * dropped_;
    const double pose[7] = {0, height, 0, 1, 0, 0, 0};
    std::copy(pose, pose + 7, q);
    std::fill(scene_.d()->qvel + 6 * dropped_, scene_.d()->qvel + 6 * dropped_ + 6, 0.0);
    ++dropped_;
    mj_kinematics(scene_.m(), scene_.d());
  }
  int count() const override { return dropped_; }
  Vec3 plateCentre(int plate) const override { return centreOf(scene_.d(), plate + 1); }
  double plateSpeed(int plate) const override {
    const double* v = scene_.d()->qvel + 6 * plate;
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  }
  double plateYawDegrees(int plate) const override {
    const double* r = scene_.d()->xmat + 9 * (plate + 1);  // row-major: local x in world is column 0
    return std::atan2(-r[6], r[0]) * 180.0 / M_PI;
  }

 private:
  static constexpr double PARKED_DEPTH = -1000.0, PARKED_SPACING = 20.0;  // m
  static Vec3 parkedAt(int i) { return {PARKED_SPACING * (i + 1), PARKED_DEPTH, 0.0}; }
  void park(int i) {
    const Vec3 p = parkedAt(i);
    const double pose[7] = {p.x, p.y, p.z, 1, 0, 0, 0};
    std::copy(pose, pose + 7, scene_.d()->qpos + 7 * i);
    std::fill(scene_.d()->qvel + 6 * i, scene_.d()->qvel + 6 * i + 6, 0.0);
  }
  static std::string xml(const RunOptions& o, int plates) {
    using namespace scene::test5;
    const bool best = o.setting == Setting::Best;
    std::ostringstream s;
    s.precision(17);
    s << header("odelab-test5", o.step, SURFACE_GRAVITY, "Euler", best ? "cone=\"elliptic\"" : "")
      << "  <size nconmax=\"" << 8 * plates + 100 << "\" njmax=\"" << 32 * plates + 400 << "\"/>\n"
      << "  <default><geom friction=\"" << NO_SLIP_FRICTION << " 0.005 0.0001\"";
    if (best) s << " solref=\"" << 2 * o.step << " 1\" solimp=\"" << BEST_SOLIMP << "\"";
    s << "/></default>\n  <worldbody>\n"
      << "    <geom type=\"box\" pos=\"0 " << -PLATFORM_THICKNESS / 2 << " 0\" size=\"" << PLATFORM_SIDE / 2 << ' '
      << PLATFORM_THICKNESS / 2 << ' ' << PLATFORM_SIDE / 2 << "\"/>\n";
    for (int i = 0; i < plates; ++i) {
      const Vec3 p = parkedAt(i);
      s << "    <body pos=\"" << p.x << ' ' << p.y << ' ' << p.z << "\">\n      <freejoint/>\n"
        << "      <geom type=\"box\" size=\"" << PLATE_WIDTH / 2 << ' ' << PLATE_THICKNESS / 2 << ' ' << PLATE_WIDTH / 2
        << "\" mass=\"" << PLATE_MASS << "\"/>\n    </body>\n";
    }
    s << "  </worldbody>\n</mujoco>\n";
    return s.str();
  }
  int plates_, dropped_ = 0;
  MujocoScene scene_;
};

class Mujoco : public EngineOf<MujocoPendulum, MujocoBall, MujocoStack, MujocoLaunch, MujocoHangingPair, MujocoBalls,
                               MujocoUpright, MujocoDominoes, MujocoPlates> {
 public:
  std::string name() const override { return "mujoco"; }
  std::string version() const override {  // mj_version(): 222 for 2.2.2
    const int v = mj_version();
    return std::to_string(v / 100) + "." + std::to_string(v / 10 % 10) + "." + std::to_string(v % 10);
  }
  // The MJCF of the scenes that the MuJoCo 3 cross-check runs (peers/wasm/mujoco3.js).
  std::string modelText(const RunOptions& o) const override {
    if (o.scene == "test2") return MujocoPendulum::xml(scene::test2::BOB_MASS, o);
    if (o.scene == "test9") return MujocoBall::xml(o);
    return "";
  }
  std::string settingText(const RunOptions& o) const override {
    const bool best = o.setting == Setting::Best;
    std::string text = "MJCF from memory, Newton solver, pyramidal cones unless said; ";
    if (o.scene == "test2" || o.scene == "test8")
      text += best ? "RK4 integrator" : "semi-implicit Euler (MuJoCo's default)";
    else if (o.scene == "test9")
      text += best ? "no restitution in MuJoCo: undamped spring contact solref \"-5e3 0\", RK4"
                   : "no restitution in MuJoCo: its default contact (solref 0.02 1, critically damped)";
    else if (o.scene == "test4")
      text += best ? "contact time constant 2 steps (solref 2h 1), solimp 0.99 0.999 0.001, elliptic cones" : "MuJoCo's defaults";
    else if (o.scene == "test1")
      text += best ? "no restitution in MuJoCo: each ball a spring-damper contact solref \"-5e3 -b\", b for its e "
                     "(damping ratio -ln e / sqrt(pi^2 + ln^2 e)), RK4"
                   : "no restitution in MuJoCo: its default contact for every ball (solref 0.02 1, critically damped)";
    else if (o.scene == "test6")
      text += std::string(best ? "contact time constant 2 steps (solref 2h 1), solimp 0.99 0.999 0.001, elliptic cones"
                               : "MuJoCo's defaults") +
              "; ball joint in generalized coordinates, friction 100 (test6's never-sliding contacts)";
    else if (o.scene == "test5")
      text += std::string(best ? "contact time constant 2 steps (solref 2h 1), solimp 0.99 0.999 0.001, elliptic cones"
                               : "MuJoCo's defaults") +
              "; every plate in the model from the start, parked 1 km below until dropped; friction 100";
    else if (o.scene == "test3")
      text += std::string(best ? "contact time constant 2 steps (solref 2h 1), solimp 0.99 0.999 0.001, elliptic cones"
                               : "MuJoCo's defaults") +
              "; friction 1.0; no sleeping in MuJoCo 2.2 (every body stepped to the end)";
    else if (o.scene == "test7")
      text += std::string(best ? "contact time constant 2 steps (solref 2h 1), elliptic cones" : "MuJoCo's defaults") +
              "; ball joints in generalized coordinates, friction 100 (test7's never-sliding contacts), no angular "
              "speed cap";
    else
      text += best ? "contact time constant 2 steps (solref 2h 1)" : "MuJoCo's defaults (solref 0.02 1)";
    return text;
  }
};

}  // namespace

// MuJoCo's own handlers append to MUJOCO_LOG.TXT in the working folder
// (and its error handler waits for Enter); these say it on standard error
// and leave no file behind.
namespace {
void onMujocoWarning(const char* message) { std::fprintf(stderr, "warning: MuJoCo: %s\n", message); }
[[noreturn]] void onMujocoError(const char* message) {
  std::fprintf(stderr, "error: MuJoCo: %s\n", message);
  std::exit(1);
}
}  // namespace

int main(int argc, char** argv) {
  mju_user_warning = onMujocoWarning;
  mju_user_error = onMujocoError;
  Mujoco mujoco;
  try {
    return odelab::peers::runPeer(argc, argv, mujoco);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
}
