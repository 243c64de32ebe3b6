// test7 - Axis system 2 (thesis 5.8): two cubes hang in a chain of ball
// joints from a fixed point, a light one (the pivot) above a heavy one, and a
// 100 kg test cube is thrown into the pivot at 30 m/s. The joints carry a
// 1000:1 mass ratio and take the hits; the thesis found the chain naturally
// stable, swinging faster with each throw, and tamed the pivot's spin after
// glancing hits with dWorldSetMaxAngularSpeed(world, 10), which applies to
// every body in the world.
//
// Measures: the largest joint error (distance between the two bodies' anchor
// points, of either joint), the pivot's largest angular speed, and the
// mechanical energy of the hanging pair after each throw, above its energy
// hanging at rest (the joints sag a little under the 5000 kg load, so "at
// rest" is measured before the first hit, not taken from the built pose).
#include <CLI/CLI.hpp>
#include <array>
#include <cmath>
#include <deque>

#include "AbstractWindow.h"
#include "Box.h"
#include "CommandLine.h"
#include "FormatValue.h"
#include "Plane.h"
#include "Sphere.h"
#include "SceneRegistry.h"
#include "shared/AngularSpeedLimit.h"
#include "shared/BodyMeasures.h"
#include "shared/SceneConstants.h"

namespace {

using namespace odelab;

using namespace scene::test7;  // the hanging pair and the throws: SceneConstants.h (shared with peers/)

constexpr int THROWS_ON_HUD = 5;
constexpr double ANCHOR_MARKER_RADIUS = 0.15;  // drawn only: it collides with nothing
// The pair's resting energy is averaged while the first throw is in the air
// (it reaches the pivot after about 0.30 s).
constexpr double REST_FROM_SECONDS = 0.05, REST_TO_SECONDS = 0.25;
// The energy after a throw is a mean over the last second before the next
// throw: the test cube may lie on the big cube and trade energy with it.
constexpr double ENERGY_MEAN_SECONDS = 1.0;
// F5 walks the max angular speed limit through these (0: no limit).
const std::vector<double> ANGULAR_SPEED_LADDER{0.0, 1.0, 3.0, 10.0, 30.0, 100.0};

// Kinetic (linear and rotational) plus potential energy of a body, with the
// potential taken from the height `restY` it was built at.
double mechanicalEnergy(dBodyID body, double gravity, double restY) {
  dMass m;
  dBodyGetMass(body, &m);
  const dReal* v = dBodyGetLinearVel(body);
  const dReal* w = dBodyGetAngularVel(body);
  dVector3 wBody, Iw;
  dMultiply1_331(wBody, dBodyGetRotation(body), w);  // R^T w: spin in body axes
  dMultiply0_331(Iw, m.I, wBody);
  const double rotational = 0.5 * (wBody[0] * Iw[0] + wBody[1] * Iw[1] + wBody[2] * Iw[2]);
  const double linear = 0.5 * m.mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return linear + rotational + m.mass * gravity * (dBodyGetPosition(body)[1] - restY);
}

// Distance between where each of the two joined bodies holds the anchor.
double ballJointError(dJointID joint) {
  dVector3 a1, a2;
  dJointGetBallAnchor(joint, a1);
  dJointGetBallAnchor2(joint, a2);
  const dReal d[3] = {a1[0] - a2[0], a1[1] - a2[1], a1[2] - a2[2]};
  return vectorLength(d);
}

class AxisSystem2 : public AbstractWindow {
 public:
  AxisSystem2() : AbstractWindow(WorldSettings{}) {
    rebindKey(SDLK_r, "R", "throw the test cube again at the pivot (Shift+R: reset the whole scene to its initial state)",
            [this](int direction) {
              if (direction > 0) {
                throwTestCube();
                return;
              }
              reset();
              notify("scene reset");
            });
    declare(Knob::real("max_angular_speed", "max angular speed, 0: off", "rad/s", angularLimit_.radPerSecond, 0.0, 1e6)
                .withOption("--max-angular-speed",
                            "dWorldSetMaxAngularSpeed(world, W) in rad/s for every body (the thesis's 10); 0: no limit")
                .withKey(SDLK_F5, "F5", "max angular speed of every body up (Shift: down): off, 1, 3, 10, 30, 100 rad/s",
                         ANGULAR_SPEED_LADDER));
    declare(Knob::integer("throws", "throws", throws_, 1, 1000)
                .withOption("--throws", "headless: how many times the test cube is thrown")
                .onlyHeadless());
    // A throw interval below one step would count throws that no step separates.
    declare(Knob::interval("throw_interval", "throw interval", throwInterval_, 1e-6, 1e4)
                .withOption("--throw-interval", "headless: simulated seconds between throws")
                .onlyHeadless());
    useContactChoices(dInfinity);  // the thesis names no friction here: never slides
  }

 protected:
  void configureWorld() override {
    angularLimit_.applyToWorld(world());
  }

  void buildScene() override {
    add<Plane>(space());
    addAnchorMarker();
    pivot_ = &add<Box>(world(), space(), PIVOT_SIDE, PIVOT_SIDE, PIVOT_SIDE, PIVOT_MASS);
    pivot_->setPosition(0.0, PIVOT_CENTRE_Y, 0.0);
    pivot_->color = Color{0.85f, 0.55f, 0.2f};
    big_ = &add<Box>(world(), space(), BIG_SIDE, BIG_SIDE, BIG_SIDE, BIG_MASS);
    big_->setPosition(0.0, BIG_CENTRE_Y, 0.0);
    big_->color = Color{0.3f, 0.5f, 0.8f};

    joints_[0] = dJointCreateBall(world(), 0);
    dJointAttach(joints_[0], pivot_->getBody(), 0);
    dJointSetBallAnchor(joints_[0], 0.0, ANCHOR_HEIGHT, 0.0);
    joints_[1] = dJointCreateBall(world(), 0);
    dJointAttach(joints_[1], pivot_->getBody(), big_->getBody());
    dJointSetBallAnchor(joints_[1], 0.0, LOWER_ANCHOR_Y, 0.0);

    testCube_ = &add<Box>(world(), space(), TEST_CUBE_SIDE, TEST_CUBE_SIDE, TEST_CUBE_SIDE, TEST_CUBE_MASS);
    testCube_->color = Color{0.8f, 0.25f, 0.25f};

    jointError_ = maxJointError_ = 0.0;
    pivotSpeed_ = maxPivotSpeed_ = 0.0;
    throwCount_ = 0;
    energyAfterThrow_.clear();
    restSum_ = 0.0;
    restSamples_ = 0;
    cubePassedPivot_ = false;
    throwTestCube();  // the scene starts with the first throw
  }

  void afterStep() override {
    jointError_ = std::max(ballJointError(joints_[0]), ballJointError(joints_[1]));
    maxJointError_ = std::max(maxJointError_, jointError_);
    pivotSpeed_ = vectorLength(dBodyGetAngularVel(pivot_->getBody()));
    maxPivotSpeed_ = std::max(maxPivotSpeed_, pivotSpeed_);
    cubePassedPivot_ = cubePassedPivot_ || beyondPivot();
    const double energy = pairEnergy();
    if (throwCount_ == 1 && simulatedTime() >= REST_FROM_SECONDS && simulatedTime() <= REST_TO_SECONDS) {
      restSum_ += energy;
      ++restSamples_;
    }
    recentEnergy_.push_back(energy);
    const size_t samples = std::max<long long>(1, std::llround(ENERGY_MEAN_SECONDS / settings().step));
    while (recentEnergy_.size() > samples) recentEnergy_.pop_front();
  }

  void addHudLines(std::vector<std::string>& lines) const override {
    // The headline (the compact HUD's line): the joint error the scene
    // measures, and how many throws it has had.
    lines.push_back("joint error " + formatValue(jointError_, 4) + " m (max " + formatValue(maxJointError_, 4) +
                    ")   throws " + std::to_string(throwCount_) + " (R throws, Shift+R resets)");
    lines.push_back("pivot angular speed " + formatValue(pivotSpeed_, 4) + " rad/s (max " +
                    formatValue(maxPivotSpeed_, 4) + ")   max angular speed " + angularLimit_.describe() + " (F5)");
    std::string energies = "swing energy of the hanging pair " + formatValue(pairEnergy() - restingEnergy(), 6) +
                           " J (1 s mean " + formatValue(swingEnergy(), 6) + ")";
    const size_t first = energyAfterThrow_.size() > THROWS_ON_HUD ? energyAfterThrow_.size() - THROWS_ON_HUD : 0;
    if (!energyAfterThrow_.empty()) energies += "; after throw";
    for (size_t i = first; i < energyAfterThrow_.size(); ++i)
      energies += " " + std::to_string(i + 1) + ": " + formatValue(energyAfterThrow_[i], 6);
    lines.push_back(energies);
  }

  // The live plot (L): the scene's headline measurement.
  bool plotValue(double& value) const override {
    value = jointError_;
    return true;
  }
  std::string plotLabel() const override { return "largest ball-joint error (m)"; }

  void addMetrics(Metrics& m) const override {
    m.set("max_joint_error", maxJointError_);
    m.set("max_angular_speed", maxPivotSpeed_);
    m.set("max_angular_speed_limit", angularLimit_.radPerSecond);
    m.set("throws", throwCount_);
    // 1 when a throw went through the pivot instead of hitting it (a soft or
    // missed contact): the joint figures then measure no hit.
    m.set("cube_passed_pivot", cubePassedPivot_ ? 1 : 0);
    m.set("resting_energy_offset", restingEnergy());
    for (size_t i = 0; i < energyAfterThrow_.size(); ++i)
      m.set("energy_after_throw_" + std::to_string(i + 1), energyAfterThrow_[i]);
  }

  void initialCamera(Camera& camera) const override { camera.lookAt({-7.0, 10.0, 14.0}, {-2.0, 7.5, 0.0}); }
  SceneBounds bounds() const override { return {{-3.0, 6.0, 0.0}, 10.0}; }

  // Throws at 0 (as built), S, 2S, ...; the pair's energy after each throw is
  // taken just before the next one (and at the end for the last). A longer
  // --seconds runs on after the last interval.
  int runHeadless() override {
    bool finite = runFor(throwInterval_);
    for (int i = 1; i < throws_ && finite; ++i) {
      throwTestCube();
      finite = runFor(throwInterval_);
    }
    if (finite) {
      recordEnergyOfLastThrow();
      if (options().seconds > simulatedTime()) runFor(options().seconds - simulatedTime());
    }
    return reportHeadless();
  }

 private:
  // A small static ball where the chain hangs from the world, so the window
  // shows the fixed point; its category and collide bits are 0, so no pair
  // with it ever reaches the near callback.
  void addAnchorMarker() {
    Sphere& marker = add<Sphere>(world(), space(), ANCHOR_MARKER_RADIUS, 1.0);
    marker.setAsFixedGeom();
    marker.setPosition(0.0, ANCHOR_HEIGHT, 0.0);
    dGeomSetCategoryBits(marker.getGeom(), 0);
    dGeomSetCollideBits(marker.getGeom(), 0);
    marker.color = Color{0.2f, 0.2f, 0.2f};
  }

  // Energy of the pivot and the big cube, zero when they hang as built.
  // The test cube's centre beyond the pivot's along the throw (+x) by more
  // than the two touching, while level with it: it went through.
  bool beyondPivot() const {
    const dReal* pivot = dBodyGetPosition(pivot_->getBody());
    const dReal* cube = dBodyGetPosition(testCube_->getBody());
    const double touching = (PIVOT_SIDE + TEST_CUBE_SIDE) / 2;
    return cube[0] - pivot[0] > touching && std::fabs(cube[1] - pivot[1]) < touching &&
           std::fabs(cube[2] - pivot[2]) < touching;
  }

  double pairEnergy() const {
    return mechanicalEnergy(pivot_->getBody(), settings().gravity, PIVOT_CENTRE_Y) +
           mechanicalEnergy(big_->getBody(), settings().gravity, BIG_CENTRE_Y);
  }

  // The pair's energy hanging at rest, relative to the built pose (negative:
  // the joints' sag), averaged before the first hit; 0 until measured.
  double restingEnergy() const { return restSamples_ ? restSum_ / restSamples_ : 0.0; }

  // Mean energy above rest over the last ENERGY_MEAN_SECONDS since the last throw.
  double swingEnergy() const {
    if (recentEnergy_.empty()) return 0.0;
    double sum = 0.0;
    for (double e : recentEnergy_) sum += e;
    return sum / recentEnergy_.size() - restingEnergy();
  }

  void recordEnergyOfLastThrow() {
    if (static_cast<int>(energyAfterThrow_.size()) < throwCount_) energyAfterThrow_.push_back(swingEnergy());
    recentEnergy_.clear();
  }

  // From THROW_DISTANCE away, level with the pivot's rest position, unturned,
  // at THROW_SPEED, aimed up just enough (sin 2a = g d / v^2, about 3.1
  // degrees) that its arc comes back to that level at the pivot.
  void throwTestCube() {
    recordEnergyOfLastThrow();
    const dBodyID body = testCube_->getBody();
    testCube_->setPosition(-THROW_DISTANCE, PIVOT_CENTRE_Y, 0.0);
    dMatrix3 unturned;
    dRSetIdentity(unturned);
    dBodySetRotation(body, unturned);
    dBodySetAngularVel(body, 0, 0, 0);
    const double elevation = 0.5 * std::asin(settings().gravity * THROW_DISTANCE / (THROW_SPEED * THROW_SPEED));
    testCube_->setLinearVelocity(THROW_SPEED * std::cos(elevation), THROW_SPEED * std::sin(elevation), 0.0);
    dBodyEnable(body);
    ++throwCount_;
  }

  // F5 or the panel changed the limit: the bodies that exist take it now.
  void onKnobChanged(const Knob&) override {
    for (const auto& object : objects())
      if (const dBodyID body = object->getBody()) angularLimit_.applyToBody(body);
  }

  AngularSpeedLimit angularLimit_{THESIS_MAX_ANGULAR_SPEED};
  int throws_ = DEFAULT_THROWS;
  double throwInterval_ = DEFAULT_THROW_INTERVAL;

  Box* pivot_ = nullptr;
  Box* big_ = nullptr;
  Box* testCube_ = nullptr;
  std::array<dJointID, 2> joints_{};
  double jointError_ = 0.0, maxJointError_ = 0.0;
  double pivotSpeed_ = 0.0, maxPivotSpeed_ = 0.0;
  bool cubePassedPivot_ = false;
  int throwCount_ = 0;
  std::vector<double> energyAfterThrow_;
  std::deque<double> recentEnergy_;  // the pair's energy at each step since the last throw, up to 1 s
  double restSum_ = 0.0;
  int restSamples_ = 0;
};

}  // namespace

ODELAB_SCENE(AxisSystem2,
             "Two cubes hang on ball joints; a 100 kg cube is thrown into the upper one at 30 m/s.")
