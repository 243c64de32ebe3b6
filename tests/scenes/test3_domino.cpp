// test3 - Domino (thesis 5.4): plates standing one behind another along a
// spiral, so that each falling plate knocks over the next: the chain reaction
// passes kinetic energy on through contacts with Coulomb friction
// (|Ft| <= mu |Fn|, contact mu 1.0 by default; F / G lower / raise it, up to
// dInfinity). The thesis's lesson is about cost: the speed of the simulation
// depends mainly on the number of active bodies, so auto-disable is on (with
// linear and angular thresholds 0.1), QuickStep runs 8 iterations and the
// step is 0.005 s; without auto-disable it is very slow, and some fallen
// plates stay active even though they do not move.
//
// Measures the fraction of dominoes that fell, how long the chain took, how
// many bodies are still active at the end, and the real-time factor.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <vector>

#include "AbstractWindow.h"
#include "Box.h"
#include "CommandLine.h"
#include "Plane.h"
#include "SceneRegistry.h"
#include "shared/BodyMeasures.h"
#include "shared/SceneConstants.h"

namespace {

using namespace odelab;

using namespace scene::test3;  // the dominoes and their spiral: SceneConstants.h (shared with peers/)
// F / G walk through these friction coefficients; the last is dInfinity.

struct Placement {
  double x, z;
  double tangentX, tangentZ;  // unit direction of the path: the way this domino falls
};

// Positions along the spiral, DOMINO_SPACING apart (arc length), inside out.
std::vector<Placement> spiralPlacements(int count) {
  std::vector<Placement> placements;
  const double growth = SPIRAL_PITCH / (2 * M_PI);  // dr / d(angle)
  double angle = 0.0;
  for (int i = 0; i < count; ++i) {
    const double r = SPIRAL_START_RADIUS + growth * angle;
    const double c = std::cos(angle), s = std::sin(angle);
    // d/d(angle) of (r cos, r sin): the path's direction of travel.
    const double dx = growth * c - r * s, dz = growth * s + r * c;
    const double length = std::hypot(dx, dz);
    placements.push_back({r * c, r * s, dx / length, dz / length});
    angle += DOMINO_SPACING / length;  // arc length ds = |d/d(angle)| d(angle)
  }
  return placements;
}

double spiralOuterRadius(int count) {
  const std::vector<Placement> p = spiralPlacements(count);
  return std::hypot(p.back().x, p.back().z);
}

WorldSettings settingsForThisScene() {
  WorldSettings settings;  // ERP 0.2, CFM 1e-6: the thesis's defaults
  settings.iterations = SCENE_ITERATIONS;
  settings.step = SCENE_STEP;
  return settings;
}

class Domino : public AbstractWindow {
 public:
  Domino() : AbstractWindow(settingsForThisScene()) {
    declare(Knob::integer("dominoes", "dominoes", dominoCount_, 2, 1000)
                .withOption("--dominoes", "number of dominoes along the spiral")
                .rebuildsScene());  // the spiral is laid when the scene is built
    // ODE's own thresholds are 0.01: there the thesis saw fallen plates stay
    // active though they did not move, and raised them to 0.1.
    declare(Knob::real("auto_disable_threshold", "auto-disable threshold", "m/s, rad/s", disableThreshold_, 0.0, 1e6)
                .withOption("--auto-disable-threshold",
                            "auto-disable linear (m/s) and angular (rad/s) velocity threshold (default the "
                            "thesis's 0.1; ODE's own is 0.01)")
                .rebuildsScene());
    declare(Knob::toggle("no_auto_disable", "auto-disable off", noAutoDisable_)
                .withOption("--no-auto-disable",
                            "keep every body active (the thesis: very slow) instead of auto-disable with thresholds 0.1")
                .rebuildsScene());
    useContactChoices(DEFAULT_MU);
  }

 protected:
  void configureWorld() override {
    dWorldSetAutoDisableFlag(world(), noAutoDisable_ ? 0 : 1);
    dWorldSetAutoDisableLinearThreshold(world(), disableThreshold_);
    dWorldSetAutoDisableAngularThreshold(world(), disableThreshold_);
  }

  void buildScene() override {
    add<Plane>(space());
    dominoes_.clear();
    fellAt_.assign(dominoCount_, -1.0);
    const std::vector<Placement> placements = spiralPlacements(dominoCount_);
    for (size_t i = 0; i < placements.size(); ++i)
      dominoes_.push_back(&placeDomino(placements[i], i == 0 ? FIRST_TILT_DEGREES : 0.0, i));
    push(*dominoes_.front(), placements.front());
  }

  void setContactSurface(dGeomID, dGeomID, dSurfaceParameters& surface) override {
    surface.mode = 0;  // Coulomb friction only
    surface.mu = contactMu();
  }

  void afterStep() override {
    for (size_t i = 0; i < dominoes_.size(); ++i)
      if (fellAt_[i] < 0 && tiltDegrees(dominoes_[i]->getBody()) > FALLEN_TILT_DEGREES) fellAt_[i] = simulatedTime();
  }

  void addHudLines(std::vector<std::string>& lines) const override {
    std::ostringstream s;
    s << std::fixed << std::setprecision(2) << "fallen " << fallenCount() << " / " << dominoes_.size() << " ("
      << fallenFraction() << ")   chain " << chainSeconds() << " s   active bodies " << activeBodies();
    lines.push_back(s.str());
    s.str("");
    s << "mu " << ContactChoices::muWords(contactMu()) << " (F lower, G raise)   auto-disable "
      << (noAutoDisable_ ? "off" : "on, thresholds " + std::to_string(disableThreshold_));
    lines.push_back(s.str());
  }

  void addMetrics(Metrics& m) const override {
    m.set("dominoes", static_cast<double>(dominoes_.size()));
    m.set("fallen_fraction", fallenFraction());
    m.set("chain_seconds", chainSeconds());
    m.set("active_bodies", activeBodies());
    m.set("auto_disable", noAutoDisable_ ? 0 : 1);
    m.set("auto_disable_threshold", disableThreshold_);
    m.set("min_fallen_tilt_degrees", minFallenTilt());
  }

  bool plotValue(double& value) const override {
    value = fallenCount();
    return true;
  }
  std::string plotLabel() const override { return "fallen dominoes"; }

  double defaultHeadlessSeconds() const override { return RUN_SECONDS; }

  void initialCamera(Camera& camera) const override {
    const double r = spiralOuterRadius(dominoCount_);
    camera.lookAt({0, 1.1 * r + 2, 1.5 * r + 4}, {0, 0, 0});
  }

  SceneBounds bounds() const override { return {{0, 1, 0}, spiralOuterRadius(dominoCount_) + 2.0}; }

 private:
  // A domino standing at `at`, facing along the path; tilted forward by
  // `tiltDegrees` about its leading bottom edge, which stays on the ground.
  Box& placeDomino(const Placement& at, double tilt, size_t index) {
    Box& domino = add<Box>(world(), space(), DOMINO_THICKNESS, DOMINO_HEIGHT, DOMINO_WIDTH, DOMINO_MASS);
    // Yaw: local x (the thickness) along the path's tangent.
    dMatrix3 yaw, lean, rotation;
    dRFromAxisAndAngle(yaw, 0, 1, 0, std::atan2(-at.tangentZ, at.tangentX));
    // Lean: turning local y toward the tangent is a rotation about up x tangent.
    dRFromAxisAndAngle(lean, at.tangentZ, 0, -at.tangentX, tilt * M_PI / 180.0);
    dMultiply0(rotation, lean, yaw, 3, 3, 3);
    dBodySetRotation(domino.getBody(), rotation);
    // Centre = pivot (leading bottom edge, on the ground) + R * (-t/2, h/2, 0).
    const dVector3 local{-DOMINO_THICKNESS / 2, DOMINO_HEIGHT / 2, 0, 0};
    dVector3 offset;
    dMultiply0(offset, rotation, local, 3, 3, 1);
    const double pivotX = at.x + at.tangentX * DOMINO_THICKNESS / 2;
    const double pivotZ = at.z + at.tangentZ * DOMINO_THICKNESS / 2;
    domino.setPosition(pivotX + offset[0], offset[1], pivotZ + offset[2]);
    const float shade = 0.6f + 0.4f * static_cast<float>(index % 6) / 5.0f;
    domino.color = Color{0.9f * shade, 0.25f + 0.2f * shade, 0.2f};
    return domino;
  }

  // Sets the domino turning about its leading bottom edge at FIRST_PUSH, so
  // the edge stays put: omega about up x tangent, v = omega x (centre - edge).
  static void push(Box& domino, const Placement& at) {
    const dVector3 omega{FIRST_PUSH * at.tangentZ, 0, -FIRST_PUSH * at.tangentX, 0};
    const dReal* centre = domino.getPosition();
    const dVector3 arm{centre[0] - (at.x + at.tangentX * DOMINO_THICKNESS / 2), centre[1],
                       centre[2] - (at.z + at.tangentZ * DOMINO_THICKNESS / 2), 0};
    dVector3 velocity;
    dCalcVectorCross3(velocity, omega, arm);
    dBodySetAngularVel(domino.getBody(), omega[0], omega[1], omega[2]);
    dBodySetLinearVel(domino.getBody(), velocity[0], velocity[1], velocity[2]);
  }

  int fallenCount() const {
    return static_cast<int>(std::count_if(fellAt_.begin(), fellAt_.end(), [](double t) { return t >= 0; }));
  }
  double fallenFraction() const { return dominoes_.empty() ? 0.0 : double(fallenCount()) / dominoes_.size(); }
  // Time at which the last domino (so far) fell: the chain's duration.
  double chainSeconds() const { return std::max(0.0, *std::max_element(fellAt_.begin(), fellAt_.end())); }
  int activeBodies() const { return bodyCount() - disabledBodyCount(); }
  // How far the fallen dominoes lean now; shows that the 30 degree threshold is safe.
  double minFallenTilt() const {
    double smallest = 180.0;
    for (size_t i = 0; i < dominoes_.size(); ++i)
      if (fellAt_[i] >= 0) smallest = std::min(smallest, tiltDegrees(dominoes_[i]->getBody()));
    return fallenCount() > 0 ? smallest : 0.0;
  }

  std::vector<Box*> dominoes_;
  std::vector<double> fellAt_;  // simulated time each domino fell; < 0 while standing
  int dominoCount_ = DEFAULT_DOMINOES;
  bool noAutoDisable_ = false;
  double disableThreshold_ = AUTO_DISABLE_THRESHOLD;
};

}  // namespace

ODELAB_SCENE(Domino,
             "A spiral of dominoes knocked over in a chain; auto-disable on.")
