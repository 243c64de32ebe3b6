#include "Measurements.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "Test10Scene.h"
#include "WorldSettings.h"
#include "shared/ApexTracker.h"
#include "shared/SceneConstants.h"
#include "shared/StepCostWindow.h"

namespace odelab::peers {

namespace {

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

long stepsFor(const RunOptions& options) {
  const double seconds = options.seconds >= 0 ? options.seconds : defaultSeconds(options.scene);
  return std::lround(seconds / options.step);
}

double distance(const Vec3& a, const Vec3& b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z); }

}  // namespace

double defaultSeconds(const std::string& scene) {
  if (scene == "test2") return scene::test2::RUN_SECONDS;
  if (scene == "test8") return scene::test8::RUN_SECONDS;
  if (scene == "test9") return scene::test9::RUN_SECONDS;
  if (scene == "test4") return scene::test4::RUN_SECONDS;
  if (scene == "test1") return scene::test1::RUN_SECONDS;
  if (scene == "test3") return scene::test3::RUN_SECONDS;
  if (scene == "test5") return scene::test5::RUN_SECONDS;
  if (scene == "test6") return scene::test6::DEFAULT_SECONDS;
  if (scene == "test7") return scene::test7::DEFAULT_THROWS * scene::test7::DEFAULT_THROW_INTERVAL;
  return 0.0;  // test10 runs launches until each is resolved
}

// test2: total energy m g y + kinetic, its largest deviation from the start.
Tally measureEnergy(Engine& engine, const RunOptions& options, Metrics& metrics) {
  auto pendulum = engine.pendulum(scene::test2::BOB_MASS, options);
  const double weight = pendulum->mass() * SURFACE_GRAVITY;
  auto energy = [&] { return weight * pendulum->centreOfMass().y + pendulum->kineticEnergy(); };
  const double start = energy();
  double low = start, high = start, last = start;
  Tally tally;
  for (long i = 0, n = stepsFor(options); i < n; ++i) {
    pendulum->step();
    last = energy();
    if (!std::isfinite(last)) {
      tally.finite = false;
      break;
    }
    low = std::min(low, last);
    high = std::max(high, last);
    ++tally.steps;
  }
  tally.simSeconds = tally.steps * options.step;
  metrics.set("energy_rel_variation", (high - low) / high);
  metrics.set("energy_drift", (last - start) / start);
  metrics.set("energy_max_deviation", std::max(high - start, start - low) / start);
  metrics.set("energy_start_J", start);
  metrics.set("energy_min_J", low);
  metrics.set("energy_max_J", high);
  metrics.set("energy_last_J", last);
  metrics.set("composite_mass_kg", pendulum->mass());
  return tally;
}

// test8: relative elongation (l - l0) / l0 of the anchor-to-centre-of-mass distance.
Tally measureElongation(Engine& engine, const RunOptions& options, Metrics& metrics) {
  const double bobMass = options.bobMass > 0 ? options.bobMass : scene::test8::HEAVY_BOB_MASS;
  auto pendulum = engine.pendulum(bobMass, options);
  const Vec3 anchor{0.0, scene::test2::ANCHOR_HEIGHT, 0.0};
  const double startLength = distance(pendulum->centreOfMass(), anchor);
  double largest = 0.0, sum = 0.0;
  Tally tally;
  for (long i = 0, n = stepsFor(options); i < n; ++i) {
    pendulum->step();
    const Vec3 centre = pendulum->centreOfMass();
    if (!finite(centre)) {
      tally.finite = false;
      break;
    }
    const double elongation = (distance(centre, anchor) - startLength) / startLength;
    largest = std::max(largest, std::fabs(elongation));
    sum += elongation;
    ++tally.steps;
  }
  tally.simSeconds = tally.steps * options.step;
  metrics.set("max_relative_elongation", largest);
  metrics.set("mean_relative_elongation", tally.steps ? sum / tally.steps : 0.0);
  metrics.set("start_length_m", startLength);
  metrics.set("composite_mass_kg", pendulum->mass());
  return tally;
}

// test9: apex error relative to the start height above the contact, after 5, 10, 20 bounces.
Tally measureBounces(Engine& engine, const RunOptions& options, Metrics& metrics) {
  using namespace scene::test9;
  auto ball = engine.ball(options);
  const Vec3 start = ball->centre();
  const double startPosition[3] = {start.x, start.y, start.z};
  ApexTracker tracker;  // the ODE program's: the vertex of the parabola through three steps
  tracker.restart(0.0, startPosition);
  std::vector<double> errors;
  double drift = 0.0;
  Tally tally;
  for (long i = 0, n = stepsFor(options); i < n; ++i) {
    ball->step();
    const Vec3 c = ball->centre();
    if (!finite(c)) {
      tally.finite = false;
      break;
    }
    ++tally.steps;
    drift = std::max(drift, std::hypot(c.x, c.z));
    const double position[3] = {c.x, c.y, c.z};
    Apex apex;
    if (tracker.update(tally.steps * options.step, position, apex))
      errors.push_back(std::fabs(apex.position[1] - tracker.releaseApex().position[1]) / (START_HEIGHT - BALL_RADIUS));
  }
  tally.simSeconds = tally.steps * options.step;
  for (int bounces : {5, 10, 20})
    metrics.set("apex_error_" + std::to_string(bounces),
                bounces <= static_cast<int>(errors.size()) ? errors[bounces - 1] : NaN);
  metrics.set("max_horizontal_drift", drift);
  metrics.set("bounces", static_cast<double>(tracker.count()));
  metrics.set("last_apex_error", errors.empty() ? NaN : errors.back());
  metrics.set("start_height_m", start.y);
  metrics.set("ball_radius_m", BALL_RADIUS);
  return tally;
}

// test4: how long the big cube stays balanced on the small one (test4's rule).
Tally measureHold(Engine& engine, const RunOptions& options, Metrics& metrics) {
  using namespace scene::test4;
  const double bigMass = options.bigMass > 0 ? options.bigMass : DEFAULT_BIG_MASS;
  auto stack = engine.stack(bigMass, options);
  double heldUntil = -1.0, maxTilt = 0.0, maxPenetration = 0.0;
  Tally tally;
  for (long i = 0, n = stepsFor(options); i < n; ++i) {
    stack->step();
    const Vec3 p = stack->bigCentre();
    if (!finite(p)) {
      tally.finite = false;
      break;
    }
    ++tally.steps;
    const double time = tally.steps * options.step;
    if (heldUntil < 0 && (std::hypot(p.x, p.z) > SIDEWAYS_LIMIT || p.y < BIG_FALLEN_HEIGHT)) heldUntil = time;
    maxTilt = std::max(maxTilt, stack->bigTiltDegrees());
    maxPenetration = std::max(maxPenetration, stack->deepestPenetration());
  }
  tally.simSeconds = tally.steps * options.step;
  const bool held = heldUntil < 0 && tally.finite;
  metrics.set("big_mass", bigMass);
  metrics.set("seconds_held", held ? tally.simSeconds : std::max(heldUntil, 0.0));
  metrics.set("held", held ? 1 : 0);
  metrics.set("max_tilt_degrees", maxTilt);
  metrics.set("max_penetration", maxPenetration);
  return tally;
}

Vec3 ballStart(int ball) {
  using namespace scene::test1;
  return {(ball - 0.5 * (BALL_COUNT - 1)) * SPACING, DROP_HEIGHT, 0.0};
}
double ballBounce(int ball) { return ball / (scene::test1::BALL_COUNT - 1.0); }

// test1: per ball the first two rebound apexes above the contact height,
// whose ratio is e^2 for an exact restitution (test1's rule and names).
Tally measureRebounds(Engine& engine, const RunOptions& options, Metrics& metrics) {
  using namespace scene::test1;
  auto balls = engine.balls(options);
  struct Record {
    double bounce = 0.0;
    ApexTracker tracker;
    double apex[2] = {NaN, NaN};
    double error() const { return std::fabs(apex[1] / apex[0] - bounce * bounce); }
    bool measured() const { return bounce >= MEASURED_FROM_BOUNCE && std::isfinite(apex[1]); }
  };
  std::vector<Record> records(balls->count());
  for (int i = 0; i < balls->count(); ++i) {
    const Vec3 c = balls->centre(i);
    const double position[3] = {c.x, c.y, c.z};
    records[i].bounce = balls->bounce(i);
    records[i].tracker.restart(0.0, position);
  }
  Tally tally;
  for (long n = stepsFor(options); tally.steps < n;) {
    balls->step();
    ++tally.steps;
    for (int i = 0; i < balls->count(); ++i) {
      const Vec3 c = balls->centre(i);
      if (!finite(c)) tally.finite = false;
      const double position[3] = {c.x, c.y, c.z};
      Apex apex;
      Record& r = records[i];
      if (r.tracker.update(tally.steps * options.step, position, apex) && r.tracker.count() <= 2)
        r.apex[r.tracker.count() - 1] = apex.position[1] - BALL_RADIUS;
    }
    if (!tally.finite) break;
  }
  tally.simSeconds = tally.steps * options.step;
  int worst = -1, measured = 0, bounced = 0, resting = 0;
  double lowest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < balls->count(); ++i) {
    const Record& r = records[i];
    if (r.measured() && (worst < 0 || r.error() > records[worst].error())) worst = i;
    measured += r.measured();
    bounced += r.tracker.count() > 0;
    const double height = balls->centre(i).y - BALL_RADIUS;
    if (balls->speed(i) < REST_SPEED && height < REST_CLEARANCE) ++resting;
    lowest = std::min(lowest, height);
  }
  metrics.set("bounce_velocity", balls->bounceVelocity());
  metrics.set("max_rebound_error", worst >= 0 ? records[worst].error() : NaN);
  metrics.set("worst_ball", worst >= 0 ? worst : NaN);
  metrics.set("balls_measured", measured);
  metrics.set("balls_bounced", bounced);
  metrics.set("balls_at_rest", resting);
  metrics.set("lowest_ball_m", lowest);
  return tally;
}

// test6: how long the 5000 kg cube stays upright on its ball joint (tilt at
// most UPRIGHT_TILT_DEGREES, centre within UPRIGHT_SIDEWAYS_METRES of where
// it was built), with test6's names; no start tilt, no angular speed cap.
Tally measureUpright(Engine& engine, const RunOptions& options, Metrics& metrics) {
  using namespace scene::test6;
  auto model = engine.axisSystem(options);
  const Vec3 built = model->bigCentre();
  double tilt = model->bigTiltDegrees(), maxTilt = tilt, maxSideways = 0.0, maxSink = 0.0, uprightUntil = -1.0;
  Tally tally;
  for (long n = stepsFor(options); tally.steps < n;) {
    model->step();
    const Vec3 p = model->bigCentre();
    tilt = model->bigTiltDegrees();
    if (!finite(p) || !std::isfinite(tilt)) {
      tally.finite = false;
      break;
    }
    ++tally.steps;
    const double sideways = std::hypot(p.x - built.x, p.z - built.z);
    maxTilt = std::max(maxTilt, tilt);
    maxSideways = std::max(maxSideways, sideways);
    if (uprightUntil < 0) maxSink = std::max(maxSink, model->smallSink());
    if (uprightUntil < 0 && (tilt > UPRIGHT_TILT_DEGREES || sideways > UPRIGHT_SIDEWAYS_METRES))
      uprightUntil = tally.steps * options.step;
  }
  tally.simSeconds = tally.steps * options.step;
  metrics.set("seconds_upright", uprightUntil < 0 ? tally.simSeconds : uprightUntil);
  metrics.set("fell", uprightUntil < 0 ? 0 : 1);
  metrics.set("max_tilt_degrees", maxTilt);
  metrics.set("final_tilt_degrees", tilt);
  metrics.set("max_sideways_metres", maxSideways);
  metrics.set("sink_while_upright_metres", maxSink);
  metrics.set("start_tilt_degrees", 0);
  metrics.set("max_angular_speed_limit", 0);
  return tally;
}

// test3: whether the chain completes (every domino past FALLEN_TILT_DEGREES),
// when the last one fell, and how many bodies are still awake at the end
// (test3's names and rule).
Tally measureChain(Engine& engine, const RunOptions& options, Metrics& metrics) {
  using namespace scene::test3;
  auto chain = engine.dominoes(options);
  std::vector<double> fellAt(chain->count(), -1.0);
  Tally tally;
  for (long n = stepsFor(options); tally.steps < n;) {
    chain->step();
    ++tally.steps;
    for (int i = 0; i < chain->count(); ++i) {
      const double tilt = chain->tiltDegrees(i);
      if (!std::isfinite(tilt)) tally.finite = false;
      if (fellAt[i] < 0 && tilt > FALLEN_TILT_DEGREES) fellAt[i] = tally.steps * options.step;
    }
    if (!tally.finite) break;
  }
  tally.simSeconds = tally.steps * options.step;
  int fallen = 0;
  double last = 0.0, leastTilt = 180.0;
  for (int i = 0; i < chain->count(); ++i) {
    if (fellAt[i] < 0) continue;
    ++fallen;
    last = std::max(last, fellAt[i]);
    leastTilt = std::min(leastTilt, chain->tiltDegrees(i));
  }
  metrics.set("dominoes", chain->count());
  metrics.set("fallen_fraction", chain->count() ? double(fallen) / chain->count() : 0.0);
  metrics.set("chain_seconds", last);
  metrics.set("active_bodies", chain->activeBodies());
  metrics.set("auto_disable", chain->sleeps() ? 1 : 0);
  metrics.set("min_fallen_tilt_degrees", fallen ? leastTilt : 0.0);
  return tally;
}

// test5: plates dropped every spawn interval (6 m up, or 1 m above the stack
// once it nears that, and clear of plates still falling) until the plate
// count is reached; a plate has landed once older than LANDING_MIN_AGE and
// slower than LANDED_SPEED. test5's names: the stack's height, how far a
// plate's centre strays from the axis and how far it turns, and the cost per
// step (wall and the process's CPU) over the last simulated second.
Tally measurePlates(Engine& engine, const RunOptions& options, Metrics& metrics) {
  using namespace scene::test5;
  auto stack = engine.plateStack(options);
  const int limit = options.plates > 0 ? options.plates : DEFAULT_PLATES;
  const double interval = options.spawnInterval > 0 ? options.spawnInterval : DEFAULT_SPAWN_INTERVAL;
  std::vector<double> bornAt;
  std::vector<bool> landed;
  size_t firstInAir = 0;
  double nextSpawn = 0.0;
  StepCostWindow wallCost(COST_WINDOW), cpuCost(COST_WINDOW);
  auto stackHeight = [&] {
    double top = 0.0;
    for (int i = 0; i < stack->count(); ++i)
      if (landed[i]) top = std::max(top, stack->plateCentre(i).y + PLATE_THICKNESS / 2);
    return top;
  };
  Tally tally;
  std::clock_t lastCpu = std::clock();
  for (long n = stepsFor(options); tally.steps < n;) {
    const auto before = std::chrono::steady_clock::now();
    stack->step();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
    ++tally.steps;
    const double time = tally.steps * options.step;
    const std::clock_t now = std::clock();
    wallCost.add(time, wall);
    cpuCost.add(time, static_cast<double>(now - lastCpu) / CLOCKS_PER_SEC);
    lastCpu = now;
    for (size_t i = firstInAir; i < landed.size(); ++i)
      if (!landed[i] && time - bornAt[i] >= LANDING_MIN_AGE && stack->plateSpeed(static_cast<int>(i)) <= LANDED_SPEED)
        landed[i] = true;
    while (firstInAir < landed.size() && landed[firstInAir]) ++firstInAir;
    if (stack->count() < limit && time >= nextSpawn) {
      double height = std::max(SPAWN_HEIGHT, stackHeight() + SPAWN_ABOVE_STACK);
      for (int i = 0; i < stack->count(); ++i)
        if (!landed[i]) height = std::max(height, stack->plateCentre(i).y + MIN_SPAWN_SEPARATION);
      stack->dropPlate(height);
      bornAt.push_back(time);
      landed.push_back(false);
      nextSpawn += interval;
    }
    bool finiteNow = true;
    for (int i = 0; i < stack->count(); ++i) finiteNow = finiteNow && finite(stack->plateCentre(i));
    if (!finiteNow) {
      tally.finite = false;
      break;
    }
  }
  tally.simSeconds = tally.steps * options.step;
  double offset = 0.0, twist = 0.0;
  for (int i = 0; i < stack->count(); ++i) {
    const Vec3 p = stack->plateCentre(i);
    offset = std::max(offset, std::hypot(p.x, p.z));
    const double yaw = std::fmod(std::fabs(stack->plateYawDegrees(i)), 90.0);  // square plates: 0 to 45 degrees
    twist = std::max(twist, std::min(yaw, 90.0 - yaw));
  }
  metrics.set("plates", stack->count());
  metrics.set("landed_plates", static_cast<double>(std::count(landed.begin(), landed.end(), true)));
  metrics.set("ms_per_step", wallCost.meanMilliseconds());
  metrics.set("cpu_ms_per_step", cpuCost.meanMilliseconds());
  metrics.set("max_axis_offset", offset);
  metrics.set("stack_height", stackHeight());
  metrics.set("plate_thickness_m", PLATE_THICKNESS);
  metrics.set("max_twist_degrees", twist);
  metrics.set("plates_frozen_in_air", 0);  // sleeping is off: nothing freezes
  metrics.set("auto_disable", 0);
  metrics.set("threads", 1);
  return tally;
}

namespace {

// The test cube is past the pivot, level with it: beyond the pivot's far
// face in x while its outline overlaps the pivot's in y and z. A cube thrown
// at the pivot gets there only through it (a contact too soft to stop it).
bool beyondPivot(const Vec3& pivot, const Vec3& cube) {
  using namespace scene::test7;
  const double touching = (PIVOT_SIDE + TEST_CUBE_SIDE) / 2;
  return cube.x - pivot.x > touching && std::fabs(cube.y - pivot.y) < touching && std::fabs(cube.z - pivot.z) < touching;
}

}  // namespace

// test7: the largest ball-joint error and the pivot's largest spin while the
// test cube is thrown at 0, S, 2S, ... (test7's headless run: DEFAULT_THROWS
// throws DEFAULT_THROW_INTERVAL apart; a longer --seconds runs on after them).
Tally measureJoints(Engine& engine, const RunOptions& options, Metrics& metrics) {
  using namespace scene::test7;
  auto pair = engine.hangingPair(options);  // built with the first throw made
  const long throwEvery = std::lround(DEFAULT_THROW_INTERVAL / options.step);
  int throws = 1;
  double maxError = 0.0, maxSpin = 0.0;
  bool passed = false;
  Tally tally;
  for (long i = 0, n = stepsFor(options); i < n; ++i) {
    if (i > 0 && i % throwEvery == 0 && throws < DEFAULT_THROWS) {
      pair->throwCube();
      ++throws;
    }
    pair->step();
    const double error = pair->jointError(), spin = pair->pivotAngularSpeed();
    if (!std::isfinite(error) || !std::isfinite(spin)) {
      tally.finite = false;
      break;
    }
    ++tally.steps;
    maxError = std::max(maxError, error);
    maxSpin = std::max(maxSpin, spin);
    passed = passed || beyondPivot(pair->pivotCentre(), pair->testCubeCentre());
  }
  tally.simSeconds = tally.steps * options.step;
  metrics.set("max_joint_error", maxError);
  metrics.set("max_angular_speed", maxSpin);
  metrics.set("max_angular_speed_limit", 0);  // no peer caps the spin (test7's --max-angular-speed 0)
  metrics.set("throws", throws);
  metrics.set("cube_passed_pivot", passed ? 1 : 0);
  return tally;
}

namespace {

enum class Outcome { Stopped, Passed, BlewUp };

// One launch, stepped until test10's rule (test10::launchOutcome) decides it.
Outcome launchAndResolve(Engine& engine, const RunOptions& options, double velocity, Tally& tally) {
  auto cube = engine.launch(velocity, options);
  for (long steps = 1;; ++steps) {
    cube->step();
    ++tally.steps;
    tally.simSeconds += options.step;
    const Vec3 p = cube->cubeCentre();
    const double vx = cube->cubeVelocityX();
    if (!finite(p) || !std::isfinite(vx)) return Outcome::BlewUp;
    switch (test10::launchOutcome(p.x, vx, velocity, steps * options.step)) {
      case test10::Outcome::Passed: return Outcome::Passed;
      case test10::Outcome::Stopped: return Outcome::Stopped;
      case test10::Outcome::InFlight: break;
    }
  }
}

}  // namespace

// test10: one launch at --velocity, or the scan for the highest velocity with
// every launch up to it stopped (test10's --find-max-velocity, without its band).
Tally measureWall(Engine& engine, const RunOptions& options, Metrics& metrics) {
  using namespace test10;
  Tally tally;
  int launched = 0, stopped = 0, passed = 0;
  auto run = [&](double velocity) {
    const Outcome outcome = launchAndResolve(engine, options, velocity, tally);
    ++launched;
    if (outcome == Outcome::Stopped) ++stopped;
    if (outcome == Outcome::Passed) ++passed;
    if (outcome == Outcome::BlewUp) tally.finite = false;
    return outcome;
  };
  const double half = CUBE_SIDE / 2;
  metrics.set("launch_velocity", options.findMaxVelocity ? 0.0 : options.velocity);
  metrics.set("geometric_prediction", (half + WALL_THICKNESS) / options.step);
  metrics.set("guaranteed_stop_velocity", (half + WALL_THICKNESS / 2) / options.step);
  metrics.set("ccd", options.ccd ? 1 : 0);
  // The scene as built, under the names test10 writes them (the constants check).
  odelab::scene::test10::reportScene(metrics);
  if (!options.findMaxVelocity) {
    run(options.velocity);
  } else {
    double maxVelocity = 0.0, firstFailure = 0.0;
    int tested = 0;
    for (double v = VelocityScan::FINE_STEP; v <= SCAN_LIMIT * (1 + 1e-12); v = VelocityScan::next(v)) {
      const Outcome outcome = run(v);
      if (outcome == Outcome::BlewUp) break;
      ++tested;
      if (outcome != Outcome::Stopped) {
        firstFailure = v;
        break;
      }
      maxVelocity = v;
    }
    metrics.set("max_velocity", maxVelocity);
    metrics.set("max_velocity_resolution", VelocityScan::resolutionAt(maxVelocity));
    metrics.set("first_failure_velocity", firstFailure);
    metrics.set("tested_velocities", tested);
  }
  metrics.set("launches", launched);
  metrics.set("stopped", stopped);
  metrics.set("passed_through", passed);
  return tally;
}

}  // namespace odelab::peers
