// replay_lab: the C++ measurement rules (Measurements.cpp) on a trajectory
// recorded from a peer (peers/wasm/parity/record.js writes one): an Engine
// whose models give back the recorded readings step by step. The metrics go
// to stdout as JSON. peers/check_parity.py runs this and the JavaScript
// rules on the same file and compares them.
//
// Usage: replay_lab FILE. Exit 0 done, 1 a short or malformed trajectory,
// 2 bad usage or a FILE that is not a regular file of at most 256 MiB
// (absent, a folder, a FIFO, a device: refused before anything is read).
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "Measurements.h"
#include "PeerScene.h"
#include "SafeFile.h"

namespace {

using namespace odelab;
using namespace odelab::peers;

struct Trajectory {
  std::map<std::string, std::string> header;
  std::vector<std::vector<double>> rows;
  double number(const std::string& key) const { return std::stod(header.at(key)); }
};

// The longest recording record.js writes is a few MiB; what is larger (or
// endless, /dev/zero) is refused before it is read.
constexpr std::size_t MAX_TRAJECTORY_BYTES = 256u << 20;

Trajectory readTrajectory(const std::string& path) {
  std::istringstream in(readBoundedFile(path, MAX_TRAJECTORY_BYTES, "the trajectory"));
  Trajectory t;
  std::string line;
  while (std::getline(in, line) && line != "rows") {
    std::istringstream fields(line);
    std::string key, value;
    fields >> key >> value;
    t.header[key] = value;
  }
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::vector<double> row;
    for (std::string field; fields >> field;) row.push_back(std::stod(field));
    t.rows.push_back(row);
  }
  if (t.rows.empty() || !t.header.count("scene")) throw std::runtime_error(path + ": no header or no rows");
  return t;
}

// The recorded readings, row 0 before any step.
class Cursor {
 public:
  explicit Cursor(const Trajectory& t) : t_(t) {}
  void step() { ++at_; }
  double at(size_t i) const {
    if (at_ >= t_.rows.size()) throw std::runtime_error("the trajectory ended before the measurement did");
    return t_.rows[at_].at(i);
  }
  Vec3 vec() const { return {at(0), at(1), at(2)}; }
  double mass() const { return t_.number("mass"); }
  const Trajectory& t() const { return t_; }

 private:
  const Trajectory& t_;
  size_t at_ = 0;
};

struct ReplayPendulum : PendulumModel {
  explicit ReplayPendulum(const Trajectory& t) : c(t) {}
  void step() override { c.step(); }
  Vec3 centreOfMass() const override { return c.vec(); }
  double kineticEnergy() const override { return c.at(3); }
  double mass() const override { return c.mass(); }
  Cursor c;
};
struct ReplayBall : BallModel {
  explicit ReplayBall(const Trajectory& t) : c(t) {}
  void step() override { c.step(); }
  Vec3 centre() const override { return c.vec(); }
  Cursor c;
};
struct ReplayStack : StackModel {
  explicit ReplayStack(const Trajectory& t) : c(t) {}
  void step() override { c.step(); }
  Vec3 bigCentre() const override { return c.vec(); }
  double bigTiltDegrees() const override { return c.at(3); }
  double deepestPenetration() const override { return c.at(4); }
  Cursor c;
};
struct ReplayLaunch : LaunchModel {
  explicit ReplayLaunch(const Trajectory& t) : c(t) {}
  void step() override { c.step(); }
  Vec3 cubeCentre() const override { return c.vec(); }
  double cubeVelocityX() const override { return c.at(3); }
  Cursor c;
};

struct ReplayHangingPair : HangingPairModel {
  explicit ReplayHangingPair(const Trajectory& t) : c(t) {}
  void step() override { c.step(); }
  void throwCube() override {}  // the throws are in the recording
  double jointError() const override { return c.at(0); }
  double pivotAngularSpeed() const override { return c.at(1); }
  Vec3 pivotCentre() const override { return {c.at(2), c.at(3), c.at(4)}; }
  Vec3 testCubeCentre() const override { return {c.at(5), c.at(6), c.at(7)}; }
  Cursor c;
};

// test1: each row holds x, y, z and speed of every ball in turn.
struct ReplayBalls : BallsModel {
  explicit ReplayBalls(const Trajectory& t) : c(t), balls(static_cast<int>(t.number("count"))) {}
  void step() override { c.step(); }
  int count() const override { return balls; }
  double bounce(int ball) const override { return ballBounce(ball); }
  Vec3 centre(int ball) const override { return {c.at(4 * ball), c.at(4 * ball + 1), c.at(4 * ball + 2)}; }
  double speed(int ball) const override { return c.at(4 * ball + 3); }
  double bounceVelocity() const override { return c.t().number("bounce_velocity"); }
  Cursor c;
  int balls;
};
struct ReplayUpright : UprightModel {
  explicit ReplayUpright(const Trajectory& t) : c(t) {}
  void step() override { c.step(); }
  Vec3 bigCentre() const override { return c.vec(); }
  double bigTiltDegrees() const override { return c.at(3); }
  double smallSink() const override { return c.at(4); }
  Cursor c;
};

// test3: each row holds every domino's tilt, then the bodies awake.
struct ReplayDominoes : DominoModel {
  explicit ReplayDominoes(const Trajectory& t) : c(t), dominoes(static_cast<int>(t.number("count"))) {}
  void step() override { c.step(); }
  int count() const override { return dominoes; }
  double tiltDegrees(int domino) const override { return c.at(domino); }
  int activeBodies() const override { return static_cast<int>(c.at(dominoes)); }
  bool sleeps() const override { return c.t().number("sleeps") != 0; }
  Cursor c;
  int dominoes;
};

// test5: each row is the plate count, then x, y, z, speed and yaw of each
// plate, read after the step; a plate dropped since shows where it was put.
struct ReplayPlates : PlateStackModel {
  explicit ReplayPlates(const Trajectory& t) : c(t) {}
  void step() override {
    c.step();
    dropped.clear();
  }
  void dropPlate(double height) override { dropped.push_back(height); }
  int recorded() const { return static_cast<int>(c.at(0)); }
  int count() const override { return recorded() + static_cast<int>(dropped.size()); }
  Vec3 plateCentre(int i) const override {
    if (i >= recorded()) return {0.0, dropped[i - recorded()], 0.0};
    return {c.at(1 + 5 * i), c.at(2 + 5 * i), c.at(3 + 5 * i)};
  }
  double plateSpeed(int i) const override { return i < recorded() ? c.at(4 + 5 * i) : 0.0; }
  double plateYawDegrees(int i) const override { return i < recorded() ? c.at(5 + 5 * i) : 0.0; }
  Cursor c;
  std::vector<double> dropped;
};

class Replay : public Engine {
 public:
  explicit Replay(const Trajectory& t) : t_(t) {}
  std::string name() const override { return "replay"; }
  std::string version() const override { return "(a recorded trajectory)"; }
  std::string settingText(const RunOptions&) const override { return "a recorded trajectory"; }
  std::unique_ptr<PendulumModel> pendulum(double, const RunOptions&) override {
    return std::make_unique<ReplayPendulum>(t_);
  }
  std::unique_ptr<BallModel> ball(const RunOptions&) override { return std::make_unique<ReplayBall>(t_); }
  std::unique_ptr<StackModel> stack(double, const RunOptions&) override { return std::make_unique<ReplayStack>(t_); }
  std::unique_ptr<LaunchModel> launch(double, const RunOptions&) override {
    return std::make_unique<ReplayLaunch>(t_);
  }
  std::unique_ptr<HangingPairModel> hangingPair(const RunOptions&) override {
    return std::make_unique<ReplayHangingPair>(t_);
  }
  std::unique_ptr<BallsModel> balls(const RunOptions&) override { return std::make_unique<ReplayBalls>(t_); }
  std::unique_ptr<UprightModel> axisSystem(const RunOptions&) override { return std::make_unique<ReplayUpright>(t_); }
  std::unique_ptr<DominoModel> dominoes(const RunOptions&) override { return std::make_unique<ReplayDominoes>(t_); }
  std::unique_ptr<PlateStackModel> plateStack(const RunOptions&) override { return std::make_unique<ReplayPlates>(t_); }

 private:
  const Trajectory& t_;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: replay_lab FILE (a trajectory from peers/wasm/parity/record.js)\n";
    return 2;
  }
  try {
    const Trajectory t = readTrajectory(argv[1]);
    Replay replay(t);
    RunOptions options;
    options.scene = t.header.at("scene");
    options.step = t.number("step");
    options.seconds = t.number("seconds");
    options.velocity = t.number("velocity");
    options.bigMass = options.bobMass = t.number("mass");
    Metrics metrics;
    if (options.scene == "test2") measureEnergy(replay, options, metrics);
    else if (options.scene == "test8") measureElongation(replay, options, metrics);
    else if (options.scene == "test9") measureBounces(replay, options, metrics);
    else if (options.scene == "test4") measureHold(replay, options, metrics);
    else if (options.scene == "test10") measureWall(replay, options, metrics);
    else if (options.scene == "test7") measureJoints(replay, options, metrics);
    else if (options.scene == "test1") measureRebounds(replay, options, metrics);
    else if (options.scene == "test6") measureUpright(replay, options, metrics);
    else if (options.scene == "test3") measureChain(replay, options, metrics);
    else if (options.scene == "test5") {
      options.plates = static_cast<int>(t.number("plates"));
      options.spawnInterval = t.number("spawn_interval");
      measurePlates(replay, options, metrics);
    }
    else throw std::runtime_error("unknown scene " + options.scene);
    std::cout << metrics.toJson();
  } catch (const ReadRefused& error) {
    std::cerr << "replay_lab: " << error.what() << '\n';
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "replay_lab: " << error.what() << '\n';
    return 1;
  }
  return 0;
}
