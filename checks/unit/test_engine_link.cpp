// The link between a scene's ODE bodies and another engine (--engine):
// what the scene does reaches the engine as edits, the engine's states come
// back into the bodies, and a state that is not finite is the engine's
// failure, said as such, with nothing written into ODE.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "Plane.h"
#include "Sphere.h"
#include "world/EngineLink.h"

namespace {

using namespace odelab;
using namespace odelab::world;

// An engine that moves every body up 1 m a step, or gives NaN when told to,
// and records the edits it is given.
class FakeEngine : public Engine {
 public:
  void build(const World& world) override {
    states_.clear();
    add(world, 0, 0, 0);
    adds = 0;
    builtBodies = static_cast<int>(world.bodies.size());
  }
  void add(const World& world, int firstBody, int, int) override {
    for (size_t i = static_cast<size_t>(firstBody); i < world.bodies.size(); ++i) {
      BodyState s;
      s.position = world.bodies[i].position;
      s.orientation = world.bodies[i].orientation;
      states_.push_back(s);
    }
    ++adds;
  }
  void remove(int body) override { removed.push_back(body); }
  void setState(int body, const BodyState& state) override {
    states_[static_cast<size_t>(body)] = state;
    ++stateEdits;
  }
  void applyForce(int, const Vec3& force, const Vec3&) override { lastForce = force; }
  void changeSettings(const World&) override {}
  void step() override {
    for (BodyState& s : states_) s.position[1] += giveNan ? std::numeric_limits<double>::quiet_NaN() : 1.0;
  }
  BodyState state(int body) const override { return states_[static_cast<size_t>(body)]; }
  const std::vector<std::string>& translationNotes() const override { return notes_; }
  double engineWallSeconds() const override { return 0.0; }
  double engineCpuSeconds() const override { return 0.0; }

  bool giveNan = false;
  int builtBodies = 0, adds = 0, stateEdits = 0;
  std::vector<int> removed;
  Vec3 lastForce{0, 0, 0};

 private:
  std::vector<BodyState> states_;
  std::vector<std::string> notes_;
};

struct Scene {
  dWorldID world = dWorldCreate();
  dSpaceID space = dSimpleSpaceCreate(nullptr);
  std::vector<std::unique_ptr<AbstractObject>> objects;
  ~Scene() {
    objects.clear();
    dSpaceDestroy(space);
    dWorldDestroy(world);
  }
  Sphere& ball(double y) {
    objects.push_back(std::make_unique<Sphere>(world, space, 0.5, 1.0));
    auto& s = static_cast<Sphere&>(*objects.back());
    s.setPosition(0, y, 0);
    return s;
  }
};

const SurfaceOf plain = [](dGeomID, dGeomID, dSurfaceParameters& s) { s.mu = 1.0; };

}  // namespace

TEST(EngineLink, StatesComeBackAndEditsGoOut) {
  Scene scene;
  scene.objects.push_back(std::make_unique<Plane>(scene.space));
  Sphere& ball = scene.ball(2.0);
  EngineLink link;
  auto owned = std::make_unique<FakeEngine>();
  FakeEngine& engine = *owned;
  link.start(std::move(owned), "fake", EngineSetting::Default, Settings{}, scene.objects, plain);
  ASSERT_EQ(engine.builtBodies, 1);
  link.sendEdits(scene.objects, plain);
  EXPECT_EQ(engine.stateEdits, 0);  // nothing changed: no edit
  link.step();
  EXPECT_EQ(dBodyGetPosition(ball.getBody())[1], 3.0);  // the engine's state, in the ODE body
  // The scene pushes the ball and adds another: a state edit, a force and an addition.
  ball.setLinearVelocity(1, 0, 0);
  dBodyAddForce(ball.getBody(), 0, 9, 0);
  scene.ball(5.0);
  link.sendEdits(scene.objects, plain);
  EXPECT_EQ(engine.stateEdits, 1);
  EXPECT_EQ(engine.lastForce[1], 9.0);
  EXPECT_EQ(dBodyGetForce(ball.getBody())[1], 0.0);  // ODE does not step here, so the link clears it
  EXPECT_EQ(engine.adds, 1);
  scene.objects.pop_back();
  link.sendEdits(scene.objects, plain);
  EXPECT_EQ(engine.removed, std::vector<int>{1});
}

TEST(EngineLink, AStateThatIsNotFiniteIsTheEnginesFailure) {
  Scene scene;
  Sphere& ball = scene.ball(2.0);
  EngineLink link;
  auto owned = std::make_unique<FakeEngine>();
  FakeEngine& engine = *owned;
  link.start(std::move(owned), "fake", EngineSetting::Default, Settings{}, scene.objects, plain);
  engine.giveNan = true;
  EXPECT_THROW(link.step(), EngineError);
  EXPECT_EQ(dBodyGetPosition(ball.getBody())[1], 2.0);  // nothing written into ODE
}
