#pragma once

// What a peer engine (Bullet, MuJoCo) must provide to run the thesis's
// measurement scenes: one small model per scene that steps and reads back the
// state the measurement needs. The measurements themselves (Measurements.cpp)
// and the command line (PeerMain.cpp) are written once for every engine, so
// the engines differ only where they really do: how a scene is built and set.
//
// Every position and velocity is given in the thesis's frame: y up, gravity
// along -y, whatever the engine's own convention.

#include <memory>
#include <string>

namespace odelab::peers {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

// "default": what a user gets from the engine with the scene built as the
// thesis describes it and nothing else changed. "best": the engine's settings
// that make this scene most accurate (named per engine in settingText).
enum class Setting { Default, Best };

struct RunOptions {
  std::string scene = "test2";
  double step = 0.001;    // s, the ODE programs' default
  double seconds = -1.0;  // < 0: the ODE program's default run length for the scene
  Setting setting = Setting::Default;
  bool ccd = false;       // continuous collision (Bullet's; MuJoCo has none)
  double velocity = 200.0;  // test10: launch velocity, m/s (the ODE program's default)
  bool findMaxVelocity = false;
  double bigMass = 0.0;   // test4: 0 means the scene's default
  double bobMass = 0.0;   // test8: 0 means the scene's default
  int plates = 0;         // test5: plates dropped, 0 means the scene's default
  double spawnInterval = 0.0;  // test5: s between plates, 0 means the scene's default
};

// test2 / test8: the composite pendulum hinged to the world.
class PendulumModel {
 public:
  virtual ~PendulumModel() = default;
  virtual void step() = 0;
  virtual Vec3 centreOfMass() const = 0;
  virtual double kineticEnergy() const = 0;  // translation and rotation, J
  virtual double mass() const = 0;           // as the engine holds it, kg
};

// test9: the bouncing ball.
class BallModel {
 public:
  virtual ~BallModel() = default;
  virtual void step() = 0;
  virtual Vec3 centre() const = 0;
};

// test4: the big cube on the small cube on the platform.
class StackModel {
 public:
  virtual ~StackModel() = default;
  virtual void step() = 0;
  virtual Vec3 bigCentre() const = 0;
  virtual double bigTiltDegrees() const = 0;      // local y against world y
  virtual double deepestPenetration() const = 0;  // m, 0 when nothing overlaps
};

// test10: one cube launched at the wall.
class LaunchModel {
 public:
  virtual ~LaunchModel() = default;
  virtual void step() = 0;
  virtual Vec3 cubeCentre() const = 0;
  virtual double cubeVelocityX() const = 0;
};

// test7: the pivot hanging from the world on a ball joint, the big cube
// hanging from the pivot on another, and the test cube thrown at the pivot
// (built with the first throw made).
class HangingPairModel {
 public:
  virtual ~HangingPairModel() = default;
  virtual void step() = 0;
  // The test cube back where it is thrown from, unturned, at the throw's velocity.
  virtual void throwCube() = 0;
  // The larger of the two joints' errors: the distance between where each of
  // the two joined bodies (or the fixed point) holds the joint's anchor, m.
  virtual double jointError() const = 0;
  virtual double pivotAngularSpeed() const = 0;  // rad/s
  virtual Vec3 pivotCentre() const = 0;
  virtual Vec3 testCubeCentre() const = 0;
};

// test1: fifty balls, ball i with restitution i/49, dropped on the ground.
class BallsModel {
 public:
  virtual ~BallsModel() = default;
  virtual void step() = 0;
  virtual int count() const = 0;
  virtual double bounce(int ball) const = 0;  // the restitution the ball was given
  virtual Vec3 centre(int ball) const = 0;
  virtual double speed(int ball) const = 0;   // m/s
  virtual double bounceVelocity() const = 0;  // m/s: slower impacts do not bounce (0: any speed; NaN: unstated)
};

// test6: the 5000 kg cube on a ball joint 2 m above the 1 kg cube resting on the ground.
class UprightModel {
 public:
  virtual ~UprightModel() = default;
  virtual void step() = 0;
  virtual Vec3 bigCentre() const = 0;
  virtual double bigTiltDegrees() const = 0;  // local y against world y
  virtual double smallSink() const = 0;       // m the small cube's lowest corner is below the ground (0: not)
};

// test3: the domino spiral, the first domino leaning and pushed.
class DominoModel {
 public:
  virtual ~DominoModel() = default;
  virtual void step() = 0;
  virtual int count() const = 0;
  virtual double tiltDegrees(int domino) const = 0;  // local y against world y
  virtual int activeBodies() const = 0;              // bodies not asleep
  virtual bool sleeps() const = 0;                   // whether the engine puts bodies to sleep here
};

// test5: square plates dropped one after another onto the platform.
class PlateStackModel {
 public:
  virtual ~PlateStackModel() = default;
  virtual void step() = 0;
  virtual void dropPlate(double height) = 0;  // centred over the platform, level, unturned, at rest
  virtual int count() const = 0;
  virtual Vec3 plateCentre(int plate) const = 0;
  virtual double plateSpeed(int plate) const = 0;     // m/s
  virtual double plateYawDegrees(int plate) const = 0;  // turn of its local x about the vertical
};

class Engine {
 public:
  virtual ~Engine() = default;
  virtual std::string name() const = 0;
  // The engine's version as the library linked reports it ("3.24"), for --version.
  virtual std::string version() const = 0;
  virtual bool hasContinuousCollision() const { return false; }
  // The scene's model as a file the engine reads (MuJoCo: MJCF); "" where
  // the engine builds the scene in code only.
  virtual std::string modelText(const RunOptions&) const { return ""; }
  // One line saying what the chosen setting is for this scene and why.
  virtual std::string settingText(const RunOptions& options) const = 0;
  virtual std::unique_ptr<PendulumModel> pendulum(double bobMass, const RunOptions& options) = 0;
  virtual std::unique_ptr<BallModel> ball(const RunOptions& options) = 0;
  virtual std::unique_ptr<StackModel> stack(double bigMass, const RunOptions& options) = 0;
  virtual std::unique_ptr<LaunchModel> launch(double velocity, const RunOptions& options) = 0;
  virtual std::unique_ptr<HangingPairModel> hangingPair(const RunOptions& options) = 0;
  virtual std::unique_ptr<BallsModel> balls(const RunOptions& options) = 0;
  virtual std::unique_ptr<UprightModel> axisSystem(const RunOptions& options) = 0;
  virtual std::unique_ptr<DominoModel> dominoes(const RunOptions& options) = 0;
  virtual std::unique_ptr<PlateStackModel> plateStack(const RunOptions& options) = 0;
};

// An engine made of its scene models: the factories written once.
template <class Pendulum, class Ball, class Stack, class Launch, class HangingPair, class Balls, class Upright,
          class Dominoes, class PlateStack>
class EngineOf : public Engine {
 public:
  std::unique_ptr<PendulumModel> pendulum(double bobMass, const RunOptions& o) override {
    return std::make_unique<Pendulum>(bobMass, o);
  }
  std::unique_ptr<BallModel> ball(const RunOptions& o) override { return std::make_unique<Ball>(o); }
  std::unique_ptr<StackModel> stack(double bigMass, const RunOptions& o) override {
    return std::make_unique<Stack>(bigMass, o);
  }
  std::unique_ptr<LaunchModel> launch(double velocity, const RunOptions& o) override {
    return std::make_unique<Launch>(velocity, o);
  }
  std::unique_ptr<HangingPairModel> hangingPair(const RunOptions& o) override {
    return std::make_unique<HangingPair>(o);
  }
  std::unique_ptr<BallsModel> balls(const RunOptions& o) override { return std::make_unique<Balls>(o); }
  std::unique_ptr<UprightModel> axisSystem(const RunOptions& o) override { return std::make_unique<Upright>(o); }
  std::unique_ptr<DominoModel> dominoes(const RunOptions& o) override { return std::make_unique<Dominoes>(o); }
  std::unique_ptr<PlateStackModel> plateStack(const RunOptions& o) override { return std::make_unique<PlateStack>(o); }
};

// The whole program: options, the scene's measurement, metrics. Exit status
// 0 done, 2 bad usage, 3 the state became non-finite.
int runPeer(int argc, char** argv, Engine& engine);

}  // namespace odelab::peers
