// Rewind by replay: a state rebuilt from the timeline equals the state the
// run first passed through, bit for bit, whatever inputs it recorded.
#include <gtest/gtest.h>

#include "AbstractWindow.h"
#include "Box.h"
#include "Plane.h"
#include "Sphere.h"

namespace {

using namespace odelab;

class DropScene : public AbstractWindow {
 public:
  DropScene() : AbstractWindow(WorldSettings{}) {
    identify("unit", "drop");
    bindKey(SDLK_b, "B", "spawn a box at a random place", [this](int) {
      const double x = std::uniform_real_distribution<double>(-1, 1)(random());
      add<Box>(world(), space(), 0.5, 0.5, 0.5, 1.0).setPosition(x, 3, 0);
    });
    bindKey(SDLK_g, "G", "gain up", [this](int direction) { gain += direction; });
    keepAcrossRewind(gain);
  }
  double gain = 1.0;

 protected:
  void buildScene() override {
    add<Plane>(space());
    add<Sphere>(world(), space(), 0.3, 1.0).setPosition(0, 2, 0);
  }
};

RunOptions headless() {
  RunOptions options;
  options.headless = true;
  return options;
}

void stepTo(AbstractWindow& scene, long long step) {
  while (scene.run().steps() < step) ASSERT_TRUE(scene.stepOnce());
}

TEST(Timeline, ReplayReproducesKeysSettingsAndDragsBitForBit) {
  DropScene scene;
  scene.initialize(headless());
  stepTo(scene, 100);
  scene.handleKey(SDLK_b, false);
  stepTo(scene, 200);
  scene.handleKey(SDLK_F3, false);  // ERP up: a setting change mid-run
  scene.handleKey(SDLK_g, false);
  stepTo(scene, 300);
  const double origin[3] = {0, 10, 0}, down[3] = {0, -1, 0};
  const PickHit hit = scene.run().pickAt(origin, down);
  ASSERT_GE(hit.objectIndex, 0);
  const double target[3] = {0.5, 2.5, 0};
  scene.beginDrag(hit, target);
  stepTo(scene, 400);
  scene.endDrag();
  stepTo(scene, 800);
  const auto firstPass = scene.run().stateHash();
  const double erp = scene.tuning().settings().erp;

  scene.replayTo(800);
  EXPECT_EQ(scene.run().stateHash(), firstPass);
  EXPECT_EQ(scene.tuning().settings().erp, erp);
  EXPECT_EQ(scene.gain, 2.0);  // restored to 1, then G replayed once

  // From an earlier snapshot, running on follows the same motion.
  scene.replayTo(250);
  EXPECT_TRUE(scene.session().time().paused());
  stepTo(scene, 800);
  EXPECT_EQ(scene.run().stateHash(), firstPass);
}

TEST(Timeline, AnInputAfterARewindReplacesTheOldFuture) {
  DropScene scene;
  scene.initialize(headless());
  stepTo(scene, 100);
  scene.handleKey(SDLK_b, false);
  stepTo(scene, 600);
  scene.replayTo(50);
  scene.handleKey(SDLK_g, false);  // a new branch: the spawn at 100 is gone
  stepTo(scene, 600);
  EXPECT_EQ(scene.run().bodyCount(), 1);
  EXPECT_EQ(scene.session().timeline().events().size(), 1u);
}

TEST(Timeline, SnapshotsEveryQuarterSecondAndStayWithinTheHorizon) {
  Timeline timeline;
  for (long long s = 250; s <= 1000; s += 250) timeline.markSnapshot(s);
  timeline.extendHorizon(1000);
  EXPECT_EQ(timeline.previousSnapshot(600), 500);
  EXPECT_EQ(timeline.previousSnapshot(250), -1);
  EXPECT_EQ(timeline.nextSnapshot(600), 750);
  EXPECT_EQ(timeline.nextSnapshot(1000), -1);
  for (long long s = 1250; s < 1250 + 300 * 250; s += 250) timeline.markSnapshot(s);
  EXPECT_EQ(timeline.snapshotCount(), Timeline::SNAPSHOT_CAPACITY);
}

TEST(DragSpring, PullsThePickedBodyTowardTheTarget) {
  DropScene scene;
  scene.initialize(headless());
  stepTo(scene, 1000);  // the sphere has landed
  const double origin[3] = {0, 10, 0}, down[3] = {0, -1, 0};
  const PickHit hit = scene.run().pickAt(origin, down);
  ASSERT_EQ(hit.objectIndex, 1);  // the sphere, not the plane
  EXPECT_NEAR(hit.point[1], 0.6, 1e-3);
  const double target[3] = {1.0, 1.5, 0.0};
  scene.beginDrag(hit, target);
  stepTo(scene, 3000);
  scene.endDrag();
  const auto metrics = scene.metrics();
  // A critically damped 2 Hz spring closes a 1.2 m gap to a few centimetres
  // (gravity sags it by g / omega^2 = 6 cm) within 2 s.
  EXPECT_NEAR(metrics.get("drag_start_distance"), std::hypot(1.0, 0.9), 1e-6);
  EXPECT_LT(metrics.get("drag_end_distance"), 0.1);
}

}  // namespace

// A run paused between marks, rewound with ',', must be able to come back
// with '.' to where it paused: past the last mark, the next stop is the
// furthest step reached.
TEST(Timeline, ForwardPastTheLastMarkReachesTheHorizon) {
  Timeline timeline;
  for (long long s = 250; s <= 1000; s += 250) timeline.markSnapshot(s);
  timeline.extendHorizon(1100);
  EXPECT_EQ(timeline.nextSnapshot(750), 1000);
  EXPECT_EQ(timeline.nextSnapshot(1000), 1100);
  EXPECT_EQ(timeline.nextSnapshot(1100), -1);
}
