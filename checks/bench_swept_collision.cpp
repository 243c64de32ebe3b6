// What the swept test (utils/SweptCollision) costs a call, by the kind of
// step, in test10's geometry (a 0.4 m cube at 200 m/s, a 0.05 m wall, the
// ground; friction and gravity need not be test10's for this), and
// beside it what one ODE step of that one-cube world costs, so the two can
// be compared as a ratio measured in the same run. Prints figures; passes
// or fails nothing (a benchmark, not a timed test).
//
//   bench_swept_collision [calls]      (default 200000 per kind)
#include <ode/ode.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>

#include "check_cli.h"
#include "shared/SweptCollision.h"

namespace {

using odelab::SweptCollision;
using Clock = std::chrono::steady_clock;

constexpr double STEP = 0.001, VELOCITY = 200.0;  // test10's defaults
constexpr double HALF = 0.2, WALL = 0.05;

struct Scene {
  dWorldID world = dWorldCreate();
  dSpaceID space = dSimpleSpaceCreate(nullptr);
  dJointGroupID contacts = dJointGroupCreate(0);
  dGeomID ground = dCreatePlane(space, 0, 1, 0, 0);
  dGeomID wall = dCreateBox(space, WALL, 6, 6);
  dBodyID cube = dBodyCreate(world);
  dGeomID cubeGeom = dCreateBox(space, 2 * HALF, 2 * HALF, 2 * HALF);
  double gravity[3] = {0, -9.81, 0};

  Scene() {
    dWorldSetGravity(world, gravity[0], gravity[1], gravity[2]);
    dGeomSetPosition(wall, 0, 3, 0);
    dMass mass;
    dMassSetBoxTotal(&mass, 1.0, 2 * HALF, 2 * HALF, 2 * HALF);
    dBodySetMass(cube, &mass);
    dGeomSetBody(cubeGeom, cube);
  }
  ~Scene() {
    dJointGroupDestroy(contacts);
    dSpaceDestroy(space);
    dWorldDestroy(world);
  }
  // The cube with its centre at x, flying at VELOCITY toward the wall.
  void place(double x) {
    dBodySetPosition(cube, x, 3, 0);
    dBodySetLinearVel(cube, VELOCITY, 0, 0);
    dBodySetAngularVel(cube, 0, 0, 0);
    const dMatrix3 identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    dBodySetRotation(cube, identity);
  }
};

void nearCallback(void* data, dGeomID a, dGeomID b) {
  auto* scene = static_cast<Scene*>(data);
  dContact contact[4];
  const int n = dCollide(a, b, 4, &contact[0].geom, sizeof(dContact));
  for (int i = 0; i < n; ++i) {
    contact[i].surface.mode = 0;
    contact[i].surface.mu = 0.5;
    dJointAttach(dJointCreateContact(scene->world, scene->contacts, &contact[i]), dGeomGetBody(a), dGeomGetBody(b));
  }
}

// Nanoseconds a call of `work`: `calls` rounds of `prepare` then `work`,
// less the same rounds of `prepare` alone (a clock read per call would
// cost as much as the sweep). The best of five tries of each.
double nanosecondsPerCall(long calls, const std::function<void()>& prepare, const std::function<void()>& work) {
  auto best = [&](const std::function<void()>& round) {
    double fastest = 1e300;
    for (int attempt = 0; attempt < 5; ++attempt) {
      const auto start = Clock::now();
      for (long i = 0; i < calls; ++i) round();
      fastest = std::min(fastest, std::chrono::duration<double, std::nano>(Clock::now() - start).count());
    }
    return fastest;
  };
  return (best([&] { prepare(), work(); }) - best(prepare)) / calls;
}

// Prints what a sweep and an ODE step cost, each measured `calls` times.
void benchmark(long calls) {
  Scene scene;
  SweptCollision sweep;
  sweep.setStaticGeoms({scene.ground, scene.wall});
  const SweptCollision::Body body = SweptCollision::describeBody(scene.cube, scene.cubeGeom);
  auto empty = [&] { dJointGroupEmpty(scene.contacts); };
  auto sweepAt = [&](double x) {
    return nanosecondsPerCall(calls, [&] { empty(), scene.place(x); },
                              [&] { sweep.sweep(body, STEP, scene.gravity, scene.world, scene.contacts); });
  };
  auto odeStepAt = [&](double x) {
    return nanosecondsPerCall(calls, [&] { empty(), scene.place(x); }, [&] {
      dSpaceCollide(scene.space, &scene, &nearCallback);
      dWorldQuickStep(scene.world, STEP);
    });
  };
  // The wall's near face is at -0.025. A cube centred at -4 is far from it;
  // at -0.4 it is within one step's travel (0.2 m) of touching. The step
  // that meets the wall: without the sweep the cube arrives 0.025 m into it
  // (centre at -0.2); with it, clamped to touching (0.001 m deep).
  const double farSweep = sweepAt(-4.0), impactSweep = sweepAt(-0.4);
  const double flightStep = odeStepAt(-4.0);
  const double plainImpact = odeStepAt(-0.2), clampedImpact = odeStepAt(-0.025 - HALF + 0.001);
  empty();
  std::printf("step %g s, cube at %g m/s, %ld calls of each\n", STEP, VELOCITY, calls);
  std::printf("sweep, flight step (no static near):  %8.1f ns\n", farSweep);
  std::printf("sweep, step of impact (clamped):      %8.1f ns\n", impactSweep);
  std::printf("ODE collide + QuickStep, flight step: %8.1f ns\n", flightStep);
  std::printf("ODE step meeting the wall, plain:     %8.1f ns\n", plainImpact);
  std::printf("ODE step meeting the wall, clamped:   %8.1f ns\n", clampedImpact);
  std::printf("sweep / ODE step, flight:             %8.3f\n", farSweep / flightStep);
}

}  // namespace

int main(int argc, char** argv) {
  long calls = 200000;
  CLI::App app{"What the swept test of --ccd costs a call beside an ODE step of test10's world; prints figures.",
               "bench_swept_collision"};
  app.add_option("calls", calls, "calls timed per kind of step (default 200000)")
      ->transform(checks::decimal())
      ->check(CLI::Range(1L, 1000000000L));
  if (auto status = checks::parse(app, argc, argv)) return *status;
  dInitODE2(0);
  benchmark(calls);  // its world is gone before ODE is closed
  dCloseODE();
  return 0;
}
