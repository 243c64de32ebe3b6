// A blow-up is named with the time and the settings in force: non-finite
// state, and finite state that has run away (speed or spin beyond the
// framework's bounds). Distance alone is no blow-up.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "AbstractWindow.h"
#include "Sphere.h"

namespace odelab {
namespace {

// One free ball, launched at a chosen velocity in a world without gravity.
class OneBall : public AbstractWindow {
 public:
  OneBall(double speed, double spin) : AbstractWindow(settingsWithoutGravity()), speed_(speed), spin_(spin) { identify("unit", "one ball"); }

 protected:
  void buildScene() override {
    Sphere& ball = add<Sphere>(world(), space(), 0.5, 1.0);
    ball.setPosition(0.0, 10.0, 0.0);
    ball.setLinearVelocity(speed_, 0.0, 0.0);
    dBodySetAngularVel(ball.getBody(), 0.0, spin_, 0.0);
  }

 private:
  static WorldSettings settingsWithoutGravity() {
    WorldSettings s;
    s.gravity = 0.0;
    return s;
  }
  double speed_, spin_;
};

std::string firstBlowUp(double speed, double spin, int steps) {
  OneBall scene(speed, spin);
  RunOptions options;
  options.headless = true;
  scene.initialize(options);
  std::string reason;
  for (int i = 0; i < steps && reason.empty(); ++i)
    if (!scene.stepOnce()) reason = scene.run().blowUpReason();
  scene.shutdown();
  return reason;
}

const char* SETTINGS = "(step 0.001, ERP 0.2, CFM 1e-06, solver quick, 20 iterations, SOR w 1.3)";

TEST(BlowUp, FastButSaneBodyIsNoBlowUp) { EXPECT_EQ(firstBlowUp(1e7, 1e3, 10), ""); }

TEST(BlowUp, NonFiniteStateIsNamedWithSettings) {
  const std::string reason = firstBlowUp(std::numeric_limits<double>::quiet_NaN(), 0.0, 1);
  EXPECT_NE(reason.find("simulation blew up: non-finite body state at t=0.001 s"), std::string::npos) << reason;
  EXPECT_NE(reason.find(SETTINGS), std::string::npos) << reason;
}

TEST(BlowUp, RunawaySpeedIsABlowUp) {
  const std::string reason = firstBlowUp(2e8, 0.0, 1);
  EXPECT_NE(reason.find("simulation blew up: runaway energy: a body moves at 2e+08 m/s"), std::string::npos) << reason;
  EXPECT_NE(reason.find(SETTINGS), std::string::npos) << reason;
}

TEST(BlowUp, RunawaySpinIsABlowUp) {
  const std::string reason = firstBlowUp(0.0, 2e8, 1);
  EXPECT_NE(reason.find("runaway energy: a body spins at"), std::string::npos) << reason;
}

TEST(BlowUp, FarAwayIsNoBlowUp) {
  // 1e7 m/s for 11 s: 1.1e8 m from the origin, and still no blow-up.
  EXPECT_EQ(firstBlowUp(1e7, 0.0, 11000), "");
}

// The blow-up test keeps the bodies' state vectors between steps: a body made
// mid-run is watched from the next step, and one destroyed (removed, or made
// static) is no longer read.
class GrowingScene : public OneBall {
 public:
  GrowingScene() : OneBall(0.0, 0.0) {}
  Sphere& addRunaway() {
    Sphere& ball = add<Sphere>(world(), space(), 0.5, 1.0);
    ball.setPosition(5.0, 10.0, 0.0);
    ball.setLinearVelocity(2e8, 0.0, 0.0);
    return ball;
  }
  void drop(const AbstractObject& object) { remove(&object); }
};

TEST(BlowUp, BodiesMadeOrDestroyedMidRunAreWatchedFromTheNextStep) {
  GrowingScene scene;
  RunOptions options;
  options.headless = true;
  scene.initialize(options);
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(scene.stepOnce());
  scene.drop(scene.addRunaway());
  EXPECT_TRUE(scene.stepOnce()) << scene.run().blowUpReason();
  scene.addRunaway().setAsFixedGeom();
  EXPECT_TRUE(scene.stepOnce()) << scene.run().blowUpReason();
  scene.addRunaway();
  EXPECT_FALSE(scene.stepOnce());
  const std::string& reason = scene.run().blowUpReason();
  EXPECT_NE(reason.find("runaway energy: a body moves at"), std::string::npos) << reason;
  scene.shutdown();
}

}  // namespace
}  // namespace odelab
