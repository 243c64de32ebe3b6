// test6 - Axis system (thesis 5.7): a 5000 kg cube held up by a ball joint
// above a 1 kg cube that rests on the ground. The joint's anchor, 2 m above
// the small cube's top, is the centre of the big cube's bottom face; nothing
// else touches the big cube. As built the system is in equilibrium, but an
// unstable one: a ball joint carries no torque, so the big cube is an
// inverted pendulum on the anchor, and any tilt grows (about e-fold every
// 0.65 s for these sizes). The thesis saw it stand for a few seconds and then
// fall; dWorldSetMaxAngularSpeed(world, 0.01) froze it, which is no fix.
//
// Measures: how long the big cube stays upright (tilt at most 1 degree and its
// centre within 0.05 m of where it was built) and the largest tilt. In exact
// arithmetic a perfectly symmetric build never leaves equilibrium, so
// --tilt-degrees can start the big cube tilted by a tiny angle to show how the
// fall depends on the size of the first disturbance.
#include <CLI/CLI.hpp>
#include <cmath>

#include "AbstractWindow.h"
#include "Box.h"
#include "CommandLine.h"
#include "FormatValue.h"
#include "Plane.h"
#include "SceneRegistry.h"
#include "shared/AngularSpeedLimit.h"
#include "shared/BodyMeasures.h"
#include "shared/SceneConstants.h"

namespace {

using namespace odelab;
// Sizes, masses and the upright rule: SceneConstants.h (shared with the peers in peers/).
using namespace scene::test6;

constexpr double MAX_START_TILT_DEGREES = 0.5;  // --tilt-degrees stays well inside "upright"

// How far the lowest corner of a box of side `side` is below the ground (0 if above).
double depthBelowGround(dBodyID body, double side) {
  const dReal* p = dBodyGetPosition(body);
  const dReal* R = dBodyGetRotation(body);
  // The lowest corner: each local axis contributes |its world y| x half the side.
  const double reach = side / 2 * (std::fabs(R[4]) + std::fabs(R[5]) + std::fabs(R[6]));
  return std::max(0.0, reach - p[1]);
}

class AxisSystem : public AbstractWindow {
 public:
  AxisSystem() : AbstractWindow(WorldSettings{}) {
    // Both act when the scene is built (the tilt) or its bodies made (the
    // limit): a change builds the scene again.
    declare(Knob::real("tilt_degrees", "start tilt", "deg", startTiltDegrees_, 0.0, MAX_START_TILT_DEGREES)
                .withOption("--tilt-degrees",
                            "start the big cube tilted about the anchor by this angle (about z), a deliberate "
                            "disturbance; default 0: the thesis's perfectly symmetric build")
                .rebuildsScene());
    declare(Knob::real("max_angular_speed", "spin limit, 0: none", "rad/s", angularLimit_.radPerSecond, 1e-3, 1e6)
                .withOption("--max-angular-speed",
                            "dWorldSetMaxAngularSpeed(world, W) for every body, in rad/s (the thesis tried 0.01); "
                            "0 or default: no limit")
                .zeroIsOff()
                .logarithmic()
                .rebuildsScene());
    useContactChoices(dInfinity);  // the thesis names no friction here: never slides
  }

  void addOptions(CLI::App& app) override {
    app.add_flag("--paused", startPaused_,
                 "window: open (and restart on R) paused on the upright system; P runs it");
  }

 protected:
  void configureWorld() override {
    angularLimit_.applyToWorld(world());
  }

  void buildScene() override {
    add<Plane>(space());
    Box& small = add<Box>(world(), space(), SMALL_SIDE, SMALL_SIDE, SMALL_SIDE, SMALL_MASS);
    small.setPosition(0.0, SMALL_SIDE / 2, 0.0);
    small.color = Color{0.85f, 0.55f, 0.2f};
    Box& big = add<Box>(world(), space(), BIG_SIDE, BIG_SIDE, BIG_SIDE, BIG_MASS);
    placeBigCube(big);
    big.color = Color{0.3f, 0.5f, 0.8f};

    dJointID ball = dJointCreateBall(world(), 0);
    dJointAttach(ball, small.getBody(), big.getBody());
    dJointSetBallAnchor(ball, 0.0, ANCHOR_HEIGHT, 0.0);

    small_ = &small;
    big_ = &big;
    const dReal* p = big.getPosition();
    builtX_ = p[0];
    builtZ_ = p[2];
    tilt_ = maxTilt_ = tiltDegrees(big.getBody());
    sideways_ = maxSideways_ = 0.0;
    maxSink_ = 0.0;
    uprightUntil_ = -1.0;
    // A window runs at once: the system stands for a few seconds, then falls.
    // --paused opens it (and R restarts it) paused on the upright system.
    if (!options().headless && startPaused_ && options().seconds <= 0 && steps() == 0) time().setPaused(true);
  }

  void afterStep() override {
    tilt_ = tiltDegrees(big_->getBody());
    const dReal* p = big_->getPosition();
    sideways_ = std::hypot(p[0] - builtX_, p[2] - builtZ_);
    maxTilt_ = std::max(maxTilt_, tilt_);
    maxSideways_ = std::max(maxSideways_, sideways_);
    if (uprightUntil_ < 0) maxSink_ = std::max(maxSink_, depthBelowGround(small_->getBody(), SMALL_SIDE));
    if (uprightUntil_ < 0 && (tilt_ > UPRIGHT_TILT_DEGREES || sideways_ > UPRIGHT_SIDEWAYS_METRES))
      uprightUntil_ = simulatedTime();
  }

  void addHudLines(std::vector<std::string>& lines) const override {
    // The headline (the compact HUD's): how long the system stood.
    if (steps() == 0 && time().paused())
      lines.push_back("upright, paused at the start: P runs it (it stands, then falls within seconds)");
    else
      lines.push_back(uprightUntil_ < 0 ? "upright for " + formatValue(simulatedTime(), 5) +
                                              " s so far (falls at tilt > 1 deg or 0.05 m sideways)"
                                        : "stood upright for " + formatValue(uprightUntil_, 5) + " s, then fell");
    lines.push_back("big cube tilt " + formatValue(tilt_, 4) + " deg (max " + formatValue(maxTilt_, 4) +
                    "), centre moved " + formatValue(sideways_, 4) + " m sideways (max " +
                    formatValue(maxSideways_, 4) + ")   small cube sank " + formatValue(maxSink_, 4) +
                    " m (max while upright)");
    std::string limits = "max angular speed " + angularLimit_.describe();
    if (startTiltDegrees_ > 0) limits += "   built tilted by " + formatValue(startTiltDegrees_, 4) + " deg";
    lines.push_back(limits);
  }

  // The live plot (L): the scene's headline measurement.
  bool plotValue(double& value) const override {
    value = tilt_;
    return true;
  }
  std::string plotLabel() const override { return "big cube's tilt (degrees)"; }

  void addMetrics(Metrics& m) const override {
    m.set("seconds_upright", uprightUntil_ < 0 ? simulatedTime() : uprightUntil_);
    m.set("fell", uprightUntil_ < 0 ? 0 : 1);
    m.set("max_tilt_degrees", maxTilt_);
    m.set("final_tilt_degrees", tilt_);
    m.set("max_sideways_metres", maxSideways_);
    m.set("sink_while_upright_metres", maxSink_);
    m.set("start_tilt_degrees", startTiltDegrees_);
    m.set("max_angular_speed_limit", angularLimit_.radPerSecond);
  }

  double defaultHeadlessSeconds() const override { return DEFAULT_SECONDS; }
  void initialCamera(Camera& camera) const override { camera.lookAt({9.0, 7.0, 15.0}, {0.0, 3.2, 0.0}); }
  SceneBounds bounds() const override { return {{0.0, 3.5, 0.0}, 9.0}; }

 private:
  // Upright, its bottom-face centre on the anchor; or turned about z around
  // the anchor by --tilt-degrees.
  void placeBigCube(Box& big) const {
    const double angle = startTiltDegrees_ * M_PI / 180.0;
    const double arm = BIG_SIDE / 2;
    big.setPosition(-arm * std::sin(angle), ANCHOR_HEIGHT + arm * std::cos(angle), 0.0);
    dMatrix3 rotation;
    dRFromAxisAndAngle(rotation, 0, 0, 1, angle);
    dBodySetRotation(big.getBody(), rotation);
  }

  AngularSpeedLimit angularLimit_;  // none unless --max-angular-speed
  double startTiltDegrees_ = 0.0;

  Box* small_ = nullptr;
  Box* big_ = nullptr;
  double builtX_ = 0.0, builtZ_ = 0.0;
  double tilt_ = 0.0, maxTilt_ = 0.0;
  double sideways_ = 0.0, maxSideways_ = 0.0;
  double maxSink_ = 0.0;        // deepest the small cube's lowest corner went below the ground while upright
  double uprightUntil_ = -1.0;  // simulated time it stopped being upright; -1 while upright
  bool startPaused_ = false;    // --paused
};

}  // namespace

ODELAB_SCENE(AxisSystem,
             "A 5000 kg cube on a ball joint above a 1 kg cube: how long does the axis stay upright?")
