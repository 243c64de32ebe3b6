// The bare ODE loop of test1's or test9's scene, for bench_overhead.sh: the
// same world, space, bodies and contacts as the program builds, stepped
// with no framework around it (no measurement, clock, timeline or checks).
//   bench_overhead_bare test1|test9 SECONDS
#include <ode/ode.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <string>
#include <vector>

#include "StateHash.h"
#include "check_cli.h"
#include "WorldSettings.h"
#include "shared/SceneConstants.h"

namespace {

constexpr int MAX_CONTACTS = 16;  // the programs' --max-contacts default

struct Scene {
  dWorldID world;
  dJointGroupID contacts;
  double bounceVelocity;
  bool perBallBounce;  // test1: the ball's index sets its bounce; test9: 1.0
};

void nearCallback(void* data, dGeomID o1, dGeomID o2) {
  const Scene& scene = *static_cast<const Scene*>(data);
  const dBodyID b1 = dGeomGetBody(o1), b2 = dGeomGetBody(o2);
  if (!b1 && !b2) return;
  dContact contact[MAX_CONTACTS];
  const int count = dCollide(o1, o2, MAX_CONTACTS, &contact[0].geom, sizeof(dContact));
  dSurfaceParameters surface{};
  surface.mode = dContactBounce;
  surface.mu = dInfinity;
  const dGeomID ball = b1 ? o1 : o2;
  surface.bounce = scene.perBallBounce ? *static_cast<const double*>(dGeomGetData(ball)) : 1.0;
  surface.bounce_vel = scene.bounceVelocity;
  for (int i = 0; i < count; ++i) {
    contact[i].surface = surface;
    dJointAttach(dJointCreateContact(scene.world, scene.contacts, &contact[i]), b1, b2);
  }
}

dBodyID addBall(dWorldID world, dSpaceID space, double radius, double mass, double x, double y) {
  const dBodyID body = dBodyCreate(world);
  dMass m;
  dMassSetSphereTotal(&m, mass, radius);
  dBodySetMass(body, &m);
  const dGeomID geom = dCreateSphere(space, radius);
  dGeomSetBody(geom, body);
  dBodySetPosition(body, x, y, 0.0);
  return body;
}

}  // namespace

int main(int argc, char** argv) {
  std::string name;
  double seconds = 0;
  CLI::App app{"The bare ODE loop of test1's or test9's scene, with no framework around it (bench_overhead.sh).",
               "bench_overhead_bare"};
  app.add_option("scene", name, "the scene whose world is stepped")->required()->check(CLI::IsMember({"test1", "test9"}));
  app.add_option("seconds", seconds, "simulated seconds to step")->required()->check(CLI::Range(0.0, 1e9));
  if (auto status = checks::parse(app, argc, argv)) return *status;
  dInitODE2(0);
  dRandSetSeed(1);  // the programs' default --seed
  odelab::WorldSettings settings;  // step 0.001, QuickStep 20 iterations, SOR 1.3, as both scenes
  settings.cfm = 0.0;
  settings.erp = name == "test1" ? 0.0 : 0.2;
  settings.gravity = (name == "test1" ? 0.25 : odelab::scene::test9::GRAVITY_FACTOR) * odelab::SURFACE_GRAVITY;
  const dWorldID world = dWorldCreate();
  dThreadingImplementationID threading = dThreadingAllocateSelfThreadedImplementation();
  dWorldSetStepThreadingImplementation(world, dThreadingImplementationGetFunctions(threading), threading);
  settings.applyTo(world);
  const dSpaceID space = dSimpleSpaceCreate(nullptr);
  dCreatePlane(space, 0, 1, 0, 0);
  Scene scene{world, dJointGroupCreate(0), 0.01, name == "test1"};
  static double bounces[50];
  std::vector<dBodyID> bodies;
  if (name == "test1") {  // 50 balls r 0.15, 1 kg, 0.4 m apart at 7 m, bounce i / 49
    for (int i = 0; i < 50; ++i) {
      bounces[i] = i / 49.0;
      bodies.push_back(addBall(world, space, 0.15, 1.0, (i - 24.5) * 0.4, 7.0));
      dGeomSetData(dBodyGetFirstGeom(bodies.back()), &bounces[i]);
    }
  } else {
    using namespace odelab::scene::test9;
    bodies.push_back(addBall(world, space, BALL_RADIUS, BALL_MASS, 0.0, START_HEIGHT));
  }
  const long long steps = std::llround(seconds / settings.step);
  double simulatedTime = 0.0;  // summed step by step, as the programs do
  for (long long i = 0; i < steps; ++i) {
    dSpaceCollide(space, &scene, &nearCallback);
    dWorldQuickStep(world, settings.step);
    dJointGroupEmpty(scene.contacts);
    simulatedTime += settings.step;
  }
  // The programs' state_hash: equal hashes show the bare loop steps the very scene the program does.
  const std::uint64_t hash = odelab::stateHash(world, steps, simulatedTime, bodies);
  std::printf("steps = %lld\nstate_hash = %llu\n", steps, static_cast<unsigned long long>(hash));
  dJointGroupDestroy(scene.contacts);
  dSpaceDestroy(space);
  dWorldDestroy(world);
  dThreadingFreeImplementation(threading);
  dCloseODE();
  return 0;
}
