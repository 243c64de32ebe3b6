// Switching the collision space (test5's Q key) moves every geom into the
// new space, from and to every kind: the quadtree space, which cannot list
// its geoms, included (window fuzzing found that switch failing).
#include <gtest/gtest.h>

#include "AbstractWindow.h"
#include "Box.h"
#include "Plane.h"

namespace odelab {
namespace {

// A 1 m cube resting on the ground plane.
class CubeOnGround : public AbstractWindow {
 public:
  CubeOnGround() : AbstractWindow(WorldSettings{}) { identify("unit", "cube on ground"); }

 protected:
  void buildScene() override {
    add<Plane>(space(), 0.0, 1.0, 0.0, 0.0);
    add<Box>(world(), space(), 1.0, 1.0, 1.0, 1.0).setPosition(0.0, 0.5, 0.0);
  }
};

const SpaceKind KINDS[] = {SpaceKind::Simple, SpaceKind::Hash, SpaceKind::SweepAndPrune, SpaceKind::QuadTree};

TEST(SpaceKind, EverySwitchKeepsEveryGeomColliding) {
  for (SpaceKind from : KINDS) {
    for (SpaceKind to : KINDS) {
      const std::string which = std::string(spaceKindName(from)) + " -> " + spaceKindName(to);
      CubeOnGround scene;
      RunOptions options;
      options.headless = true;
      scene.initialize(options);
      scene.setSpaceKind(from);
      for (int i = 0; i < 100; ++i) ASSERT_TRUE(scene.stepOnce()) << which;
      scene.setSpaceKind(to);
      EXPECT_EQ(scene.run().spaceKind(), to) << which;
      EXPECT_EQ(dSpaceGetNumGeoms(scene.run().space()), 2) << which;
      for (int i = 0; i < 500; ++i) ASSERT_TRUE(scene.stepOnce()) << which;
      // Still held up by the ground: the cube's centre 0.5 m above it, to
      // within the contacts' penetration (ERP 0.2, CFM 1e-6: well under 1 cm).
      EXPECT_GT(scene.run().contactsLastStep(), 0) << which;
      const dReal* position = dBodyGetPosition(scene.run().objects()[1]->getBody());
      EXPECT_NEAR(position[1], 0.5, 0.01) << which;
      scene.shutdown();
    }
  }
}

}  // namespace
}  // namespace odelab
