// The swept test of utils/SweptCollision against exact times of impact: a
// box and a sphere, face on, turned and turning, against a wall (a static
// box), a plane and a static sphere. The sweep reports the first fraction of
// the motion at which ODE's dCollide finds an overlap of at most the depth
// asked for, so the answer lies between the exact time of touching t and
// t + depth / speed (speed: how far a point of the body may move per unit
// fraction), never before t.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/SweptCollision.h"

namespace {

using odelab::Impact;
using odelab::StepMotion;
using odelab::SweptCollision;
using odelab::timeOfImpact;

constexpr double DEPTH = 1e-3;  // m: the overlap asked for
constexpr double SIDE = 0.4, HALF = SIDE / 2;
constexpr double WALL_THICKNESS = 0.05;

struct Scene {
  dWorldID world = dWorldCreate();
  dSpaceID space = dSimpleSpaceCreate(nullptr);
  dJointGroupID contacts = dJointGroupCreate(0);
  ~Scene() {
    dJointGroupDestroy(contacts);
    dSpaceDestroy(space);
    dWorldDestroy(world);
  }
  // A moving box or sphere on a body of 1 kg at p.
  dGeomID movingBox(double x, double y, double z) {
    dGeomID geom = dCreateBox(space, SIDE, SIDE, SIDE);
    return onBody(geom, x, y, z);
  }
  dGeomID movingSphere(double radius, double x, double y, double z) {
    return onBody(dCreateSphere(space, radius), x, y, z);
  }
  dGeomID onBody(dGeomID geom, double x, double y, double z) {
    dBodyID body = dBodyCreate(world);
    dMass mass;
    dMassSetBoxTotal(&mass, 1.0, SIDE, SIDE, SIDE);
    dBodySetMass(body, &mass);
    dGeomSetBody(geom, body);
    dBodySetPosition(body, x, y, z);
    return geom;
  }
  // The wall: a static box 0.05 thick along x, 6 x 6, standing on y = 0 across x = 0 (test10's).
  dGeomID wall() {
    dGeomID box = dCreateBox(space, WALL_THICKNESS, 6.0, 6.0);
    dGeomSetPosition(box, 0.0, 3.0, 0.0);
    return box;
  }
  dGeomID ground() { return dCreatePlane(space, 0, 1, 0, 0); }  // y = 0, solid below
};

void turn(dGeomID geom, double ax, double ay, double az, double angle) {
  dMatrix3 r;
  dRFromAxisAndAngle(r, ax, ay, az, angle);
  dBodySetRotation(dGeomGetBody(geom), r);
}

StepMotion translation(double dx, double dy, double dz) {
  StepMotion m;
  m.travel[0] = dx, m.travel[1] = dy, m.travel[2] = dz;
  return m;
}

// Asserts that the sweep found the touching at `exact` (within what the
// depth allows at `speed`) and that the pose there overlaps, as ODE sees it.
void expectImpactAt(const Impact& impact, double exact, double speed) {
  ASSERT_EQ(impact.kind, Impact::At);
  EXPECT_GE(impact.fraction, exact - 1e-12);
  EXPECT_LE(impact.fraction, exact + DEPTH / speed + 1e-12);
}

TEST(SweptCollision, FaceOnBoxMeetsTheWallWhereItsFaceReachesIt) {
  Scene scene;
  dGeomID cube = scene.movingBox(-1.0, 3.0, 0.0);
  dGeomID wall = scene.wall();
  // Leading face at x = -0.8, wall's near face at -0.025: 0.775 m of a 2 m travel.
  const Impact impact = timeOfImpact(dGeomGetBody(cube), cube, translation(2.0, 0, 0), wall, DEPTH);
  expectImpactAt(impact, 0.775 / 2.0, 2.0);
  // The body is left where it was.
  EXPECT_DOUBLE_EQ(dBodyGetPosition(dGeomGetBody(cube))[0], -1.0);
}

TEST(SweptCollision, TurnedBoxMeetsTheWallWithItsLeadingCorner) {
  Scene scene;
  dGeomID cube = scene.movingBox(-2.0, 3.0, 0.3);
  turn(cube, 1.0, 2.0, 3.0, 0.7);
  dGeomID wall = scene.wall();
  // The leading corner is half-width along x ahead of the centre.
  const dReal* r = dGeomGetRotation(cube);
  const double reach = HALF * (std::fabs(r[0]) + std::fabs(r[1]) + std::fabs(r[2]));
  const double gap = (-WALL_THICKNESS / 2) - (-2.0 + reach);
  const Impact impact = timeOfImpact(dGeomGetBody(cube), cube, translation(5.0, 0, 0), wall, DEPTH);
  expectImpactAt(impact, gap / 5.0, 5.0);
}

TEST(SweptCollision, TurnedBoxMeetsThePlaneWithItsLowestCorner) {
  Scene scene;
  dGeomID cube = scene.movingBox(0.0, 2.0, 0.0);
  turn(cube, -0.4, 0.2, 1.0, 2.1);
  dGeomID ground = scene.ground();
  const dReal* r = dGeomGetRotation(cube);
  const double lowest = 2.0 - HALF * (std::fabs(r[4]) + std::fabs(r[5]) + std::fabs(r[6]));
  // Falling 3 m and moving sideways 4 m: 5 m of travel per unit fraction.
  const Impact impact = timeOfImpact(dGeomGetBody(cube), cube, translation(4.0, -3.0, 0), ground, DEPTH);
  expectImpactAt(impact, lowest / 3.0, 5.0);
}

// The height of the lowest corner of a cube centred at height y0 - 3 s,
// turned from its start by the angle `spin` s about z (exact, brute force).
double lowestCorner(double s, double y0, double fall, double spin, const dReal* r0) {
  double lowest = 1e300;
  const double a = spin * s, c = std::cos(a), sn = std::sin(a);
  for (int corner = 0; corner < 8; ++corner) {
    const double local[3] = {corner & 1 ? HALF : -HALF, corner & 2 ? HALF : -HALF, corner & 4 ? HALF : -HALF};
    double x = 0, y = 0;
    for (int k = 0; k < 3; ++k) x += r0[k] * local[k], y += r0[4 + k] * local[k];
    lowest = std::min(lowest, y0 - fall * s + sn * x + c * y);  // y row of the turn about z
  }
  return lowest;
}

TEST(SweptCollision, TurningBoxMeetsThePlaneWhereItsCornerFirstReachesIt) {
  Scene scene;
  dGeomID cube = scene.movingBox(0.0, 1.0, 0.0);
  turn(cube, 1.0, 1.0, 0.0, 0.3);
  dGeomID ground = scene.ground();
  StepMotion motion = translation(0, -1.5, 0);
  const double spin = 6.0;  // rad over the motion, about z
  motion.turn[2] = spin;
  const dReal* r0 = dGeomGetRotation(cube);
  dReal start[12];
  for (int k = 0; k < 12; ++k) start[k] = r0[k];
  // The exact first touching: scan finely for the first sign change, then bisect.
  double before = 0.0, after = -1.0;
  for (int i = 1; i <= 100000 && after < 0; ++i) {
    const double s = i / 100000.0;
    if (lowestCorner(s, 1.0, 1.5, spin, start) <= 0.0) after = s;
    else before = s;
  }
  ASSERT_GT(after, 0.0);
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (before + after);
    (lowestCorner(mid, 1.0, 1.5, spin, start) <= 0.0 ? after : before) = mid;
  }
  const double speed = 1.5 + spin * HALF * std::sqrt(3.0);  // the sweep's bound on a point's motion
  const Impact impact = timeOfImpact(dGeomGetBody(cube), cube, motion, ground, DEPTH);
  expectImpactAt(impact, after, speed);
  // The same motion without the turn would have met the plane elsewhere:
  // the turn is taken into account, not ignored.
  const double unturned = (1.0 - HALF * (std::fabs(start[4]) + std::fabs(start[5]) + std::fabs(start[6]))) / 1.5;
  EXPECT_GT(std::fabs(impact.fraction - unturned), 10 * DEPTH / speed);
}

TEST(SweptCollision, SphereMeetsThePlaneAndTheWall) {
  Scene scene;
  dGeomID ball = scene.movingSphere(0.25, -1.0, 2.0, 0.0);
  dGeomID ground = scene.ground();
  dGeomID wall = scene.wall();
  // Down 4 m: the ball's bottom (1.75 m up) meets the plane at 1.75 / 4.
  expectImpactAt(timeOfImpact(dGeomGetBody(ball), ball, translation(0, -4.0, 0), ground, DEPTH), 1.75 / 4.0, 4.0);
  // Along x 3 m, spinning (a sphere's turn changes nothing): its front at
  // -0.75 meets the wall's near face at -0.025.
  StepMotion motion = translation(3.0, 0, 0);
  motion.turn[1] = 50.0;
  const double speed = 3.0 + 50.0 * 0.25;
  expectImpactAt(timeOfImpact(dGeomGetBody(ball), ball, motion, wall, DEPTH), 0.725 / 3.0, speed);
}

TEST(SweptCollision, SphereAndBoxMeetAStaticSphere) {
  Scene scene;
  dGeomID post = dCreateSphere(scene.space, 0.5);
  dGeomSetPosition(post, 0.0, 3.0, 0.0);
  // A ball of 0.25 from (-2, 3.2, 0) along +x: touches when the centres are
  // 0.75 apart: x = -sqrt(0.75^2 - 0.2^2).
  dGeomID ball = scene.movingSphere(0.25, -2.0, 3.2, 0.0);
  const double meet = -std::sqrt(0.75 * 0.75 - 0.2 * 0.2);
  expectImpactAt(timeOfImpact(dGeomGetBody(ball), ball, translation(4.0, 0, 0), post, DEPTH), (meet + 2.0) / 4.0,
                 4.0);
  // A face-on cube from (0, 5, 0) falling: its bottom face (y - 0.2) meets
  // the top of the post (3.5).
  dGeomID cube = scene.movingBox(0.0, 5.0, 0.0);
  expectImpactAt(timeOfImpact(dGeomGetBody(cube), cube, translation(0, -3.0, 0), post, DEPTH), (5.0 - 0.2 - 3.5) / 3.0,
                 3.0);
}

TEST(SweptCollision, MissesAndTouchingAreTold) {
  Scene scene;
  dGeomID cube = scene.movingBox(-1.0, 3.0, 0.0);
  dGeomID wall = scene.wall();
  EXPECT_EQ(timeOfImpact(dGeomGetBody(cube), cube, translation(0.5, 0, 0), wall, DEPTH).kind, Impact::None);
  EXPECT_EQ(timeOfImpact(dGeomGetBody(cube), cube, translation(-5.0, 0, 0), wall, DEPTH).kind, Impact::None);
  // Passing over the top of the 6 m wall.
  dBodySetPosition(dGeomGetBody(cube), -1.0, 6.3, 0.0);
  EXPECT_EQ(timeOfImpact(dGeomGetBody(cube), cube, translation(2.0, 0, 0), wall, DEPTH).kind, Impact::None);
  dBodySetPosition(dGeomGetBody(cube), -0.2, 3.0, 0.0);  // overlapping the near face
  EXPECT_EQ(timeOfImpact(dGeomGetBody(cube), cube, translation(2.0, 0, 0), wall, DEPTH).kind,
            Impact::AlreadyTouching);
}

TEST(SweptCollision, SeparationBoundIsZeroOnlyWhenTouchingAndNeverAboveTheDistance) {
  Scene scene;
  dGeomID cube = scene.movingBox(-1.0, 3.0, 0.0);
  dGeomID wall = scene.wall();
  EXPECT_NEAR(odelab::separationBound(cube, wall), 0.775, 1e-12);  // face to face: the distance
  turn(cube, 0.0, 0.0, 1.0, M_PI / 4);  // an edge first: its half-width along x is 0.2 sqrt 2
  EXPECT_NEAR(odelab::separationBound(cube, wall), 1.0 - 0.025 - HALF * std::sqrt(2.0), 1e-12);
  dBodySetPosition(dGeomGetBody(cube), -0.2, 3.0, 0.0);
  EXPECT_LE(odelab::separationBound(cube, wall), 0.0);
}

// Turned boxes of random sizes at random poses: the bound is positive
// exactly where ODE's own box-box test finds no contact (the separating
// axis theorem: the edge-edge axes decide some of these), and an edge-edge
// pose has its exact distance.
TEST(SweptCollision, SeparationBoundAgreesWithOdesBoxBoxTestForTurnedBoxes) {
  Scene scene;
  dGeomID a = scene.movingBox(0.0, 0.0, 0.0);
  dGeomID b = dCreateBox(scene.space, 1.0, 0.3, 0.6);  // static
  dRandSetSeed(7);
  auto uniform = [](double lo, double hi) { return lo + (hi - lo) * dRandReal(); };
  int apart = 0, touching = 0;
  for (int i = 0; i < 4000; ++i) {
    dGeomBoxSetLengths(a, uniform(0.1, 1.0), uniform(0.1, 1.0), uniform(0.1, 1.0));
    turn(a, uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(0, M_PI));
    dBodySetPosition(dGeomGetBody(a), uniform(-1.2, 1.2), uniform(-1.2, 1.2), uniform(-1.2, 1.2));
    dMatrix3 r;
    dRFromAxisAndAngle(r, uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(0, M_PI));
    dGeomSetRotation(b, r);
    const double bound = odelab::separationBound(a, b);
    if (std::fabs(bound) < 1e-9) continue;  // grazing: either answer is right
    dContactGeom contact;
    const bool overlap = dCollide(a, b, 1, &contact, sizeof(contact)) > 0;
    EXPECT_EQ(bound <= 0.0, overlap) << "case " << i << ": bound " << bound;
    (overlap ? touching : apart) += 1;
  }
  EXPECT_GT(apart, 500);
  EXPECT_GT(touching, 500);
  // Two unit cubes with crossed edges leading toward each other, 0.05 m
  // apart: a turned 45 degrees about z (its edge along z reaches x =
  // sqrt 2 / 2), b about y (its edge along y reaches back as far). Only the
  // edge-edge axis z x y separates them; the bound is their distance.
  dGeomBoxSetLengths(a, 1.0, 1.0, 1.0);
  turn(a, 0.0, 0.0, 1.0, M_PI / 4);
  dBodySetPosition(dGeomGetBody(a), 0.0, 0.0, 0.0);
  dGeomBoxSetLengths(b, 1.0, 1.0, 1.0);
  dMatrix3 r;
  dRFromAxisAndAngle(r, 0.0, 1.0, 0.0, M_PI / 4);
  dGeomSetRotation(b, r);
  dGeomSetPosition(b, std::sqrt(2.0) + 0.05, 0.0, 0.0);
  EXPECT_NEAR(odelab::separationBound(a, b), 0.05, 1e-12);
  dGeomSetPosition(b, std::sqrt(2.0) - 0.05, 0.0, 0.0);
  EXPECT_LT(odelab::separationBound(a, b), 0.0);
}

// The sweep in a step of a world: a cube corner first at 10,000 m/s toward
// a wall (10 m per step) is moved to the wall with its velocity untouched,
// and the contacts stop it there.
TEST(SweptCollision, CornerFirstCubeAt10000IsStoppedByContactsNotByAVelocityEdit) {
  Scene scene;
  dWorldSetGravity(scene.world, 0, -9.823, 0);
  dWorldSetERP(scene.world, 0.3);
  dWorldSetCFM(scene.world, 0.0);
  dGeomID cube = scene.movingBox(-4.0, 3.0, 0.0);
  turn(cube, 1.0, 1.0, 1.0, 0.5);
  dBodyID body = dGeomGetBody(cube);
  dBodySetLinearVel(body, 10000.0, 0, 0);
  dGeomID wall = scene.wall();
  SweptCollision sweep;
  sweep.setStaticGeoms({scene.ground(), wall});
  const double step = 0.001, gravity[3] = {0, -9.823, 0};
  const odelab::SweepResult result = sweep.sweep(body, cube, step, gravity, scene.world, scene.contacts);
  EXPECT_EQ(result, odelab::SweepResult::Clamped);
  EXPECT_EQ(dBodyGetLinearVel(body)[0], 10000.0);
  EXPECT_EQ(sweep.counts().clamps, 1);
  EXPECT_GT(sweep.counts().speculativeContacts, 0);
  // Clamped touching: the overlap is at most the depth.
  EXPECT_LE(odelab::separationBound(cube, wall), 0.0);
  EXPECT_GE(odelab::separationBound(cube, wall), -DEPTH);
  // Collide and step as the framework does; then the cube's centre is still
  // short of the wall's mid-plane and it moves no longer at 10,000 m/s.
  auto nearCallback = [](void* data, dGeomID a, dGeomID b) {
    auto* s = static_cast<Scene*>(data);
    dContact contacts[16];
    const int n = dCollide(a, b, 16, &contacts[0].geom, sizeof(dContact));
    if (!dGeomGetBody(a) && !dGeomGetBody(b)) return;  // static pairs: as the framework
    for (int i = 0; i < n; ++i) {
      contacts[i].surface.mode = 0;
      contacts[i].surface.mu = dInfinity;
      dJointAttach(dJointCreateContact(s->world, s->contacts, &contacts[i]), dGeomGetBody(a), dGeomGetBody(b));
    }
  };
  for (int i = 0; i < 20; ++i) {
    if (i > 0) sweep.sweep(body, cube, step, gravity, scene.world, scene.contacts);
    dSpaceCollide(scene.space, &scene, nearCallback);
    dWorldQuickStep(scene.world, step);
    dJointGroupEmpty(scene.contacts);
    EXPECT_LT(dBodyGetPosition(body)[0], 0.0) << "step " << i;
  }
  EXPECT_LT(std::fabs(dBodyGetLinearVel(body)[0]), 100.0);
}

// A cube sliding along the ground (touching it, 0.5 mm deep) at 10,000 m/s
// toward the wall is still moved to the wall: moving on along the ground
// takes it no deeper into the ground. One falling into the ground is not
// moved (the ground's contact stops it first).
TEST(SweptCollision, BoxSlidingOnTheGroundIsStillMovedToTheWall) {
  Scene scene;
  dGeomID cube = scene.movingBox(-4.0, HALF - 0.0005, 0.0);
  dBodyID body = dGeomGetBody(cube);
  dBodySetLinearVel(body, 10000.0, 0, 0);
  SweptCollision sweep;
  dGeomID wall = scene.wall();
  sweep.setStaticGeoms({scene.ground(), wall});
  const double noGravity[3] = {0, 0, 0};
  EXPECT_EQ(sweep.sweep(body, cube, 0.001, noGravity, scene.world, scene.contacts), odelab::SweepResult::Clamped);
  EXPECT_LE(odelab::separationBound(cube, wall), 0.0);
  EXPECT_GE(odelab::separationBound(cube, wall), -DEPTH);
  dBodySetPosition(body, -4.0, HALF - 0.0005, 0.0);
  dBodySetLinearVel(body, 10000.0, -100.0, 0);  // into the ground as well: 0.1 m deeper by the wall
  EXPECT_EQ(sweep.sweep(body, cube, 0.001, noGravity, scene.world, scene.contacts), odelab::SweepResult::Touching);
  EXPECT_EQ(dBodyGetPosition(body)[0], -4.0);
}

}  // namespace
