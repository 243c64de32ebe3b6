// The state hash tells two states apart even where no body exists yet
// (test10 before its first launch, a scene's marks at its start): the step
// count, the simulated time and the world's settings are part of it.
#include <gtest/gtest.h>

#include "AbstractWindow.h"
#include "Plane.h"

namespace {

using namespace odelab;

// A ground and nothing else: no body at all.
class EmptyScene : public AbstractWindow {
 public:
  explicit EmptyScene(WorldSettings settings = {}) : AbstractWindow(settings) { identify("unit", "empty"); }

 protected:
  void buildScene() override { add<Plane>(space()); }
};

RunOptions headless() {
  RunOptions options;
  options.headless = true;
  return options;
}

TEST(StateHash, AnEmptyWorldHashesItsStepCount) {
  EmptyScene scene;
  scene.initialize(headless());
  ASSERT_EQ(scene.run().bodyCount(), 0);
  const auto atStart = scene.run().stateHash();
  ASSERT_TRUE(scene.stepOnce());
  EXPECT_NE(scene.run().stateHash(), atStart) << "after one step";
}

TEST(StateHash, EmptyWorldsWithOtherSettingsHashApart) {
  WorldSettings other;
  other.erp = 0.5;
  EmptyScene first, second(other);
  first.initialize(headless());
  second.initialize(headless());
  ASSERT_NE(first.tuning().settings().erp, second.tuning().settings().erp);
  EXPECT_NE(first.run().stateHash(), second.run().stateHash());
}

TEST(StateHash, OneStateHashesAlike) {
  EmptyScene first, second;
  first.initialize(headless());
  second.initialize(headless());
  ASSERT_TRUE(first.stepOnce());
  ASSERT_TRUE(second.stepOnce());
  EXPECT_EQ(first.run().stateHash(), second.run().stateHash());
}

}  // namespace
