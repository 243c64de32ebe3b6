// attach() against the analytic mass, centre of mass and inertia of the
// test2 pendulum: a rod [3.0, 0.1, 0.1] of 0.1 kg and a sphere of radius 0.3
// and 0.33 kg centred 3.3 m from the anchor.
#include <gtest/gtest.h>

#include <cmath>

#include "Box.h"
#include "Sphere.h"

namespace {

using odelab::Box;
using odelab::Sphere;

constexpr double ROD_MASS = 0.1, SPHERE_MASS = 0.33, RADIUS = 0.3;
constexpr double ROD_X = 1.5, SPHERE_X = 3.3, Y = 7.0;
constexpr double TOLERANCE = 1e-12;

struct World {
  dWorldID world = dWorldCreate();
  dSpaceID space = dSimpleSpaceCreate(nullptr);
  ~World() {
    dSpaceDestroy(space);
    dWorldDestroy(world);
  }
};

double centreX() { return (ROD_MASS * ROD_X + SPHERE_MASS * SPHERE_X) / (ROD_MASS + SPHERE_MASS); }

// Inertia about the composite's centre, world axes, for the unrotated build.
void expectedInertia(double I[3][3]) {
  const double c = centreX();
  const double rodXX = ROD_MASS / 12.0 * (0.1 * 0.1 + 0.1 * 0.1);
  const double rodYY = ROD_MASS / 12.0 * (3.0 * 3.0 + 0.1 * 0.1);
  const double sphere = 0.4 * SPHERE_MASS * RADIUS * RADIUS;
  // Parallel axis: offsets are along x only, so they add to yy and zz.
  const double shift = ROD_MASS * (ROD_X - c) * (ROD_X - c) + SPHERE_MASS * (SPHERE_X - c) * (SPHERE_X - c);
  const double xx = rodXX + sphere, yy = rodYY + sphere + shift;
  const double value[3][3] = {{xx, 0, 0}, {0, yy, 0}, {0, 0, yy}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) I[i][j] = value[i][j];
}

TEST(Attach, MassCentreAndInertiaMatchTheAnalyticSums) {
  World w;
  Box rod(w.world, w.space, 3.0, 0.1, 0.1, ROD_MASS);
  Sphere bob(w.world, w.space, RADIUS, SPHERE_MASS);
  rod.setPosition(ROD_X, Y, 0);
  bob.setPosition(SPHERE_X, Y, 0);

  ASSERT_TRUE(bob.attach(rod));
  ASSERT_EQ(bob.getBody(), rod.getBody());

  dMass m;
  dBodyGetMass(rod.getBody(), &m);
  EXPECT_NEAR(m.mass, ROD_MASS + SPHERE_MASS, TOLERANCE);
  // ODE keeps the centre of mass at the body origin; the body moved there.
  EXPECT_NEAR(m.c[0], 0, TOLERANCE);
  const dReal* p = dBodyGetPosition(rod.getBody());
  EXPECT_NEAR(p[0], centreX(), TOLERANCE);
  EXPECT_NEAR(p[1], Y, TOLERANCE);
  EXPECT_NEAR(p[2], 0, TOLERANCE);

  double I[3][3];
  expectedInertia(I);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(m.I[i * 4 + j], I[i][j], 1e-12) << "I[" << i << "][" << j << "]";

  // Both geoms stay where they were in the world.
  EXPECT_NEAR(dGeomGetPosition(rod.getGeom())[0], ROD_X, TOLERANCE);
  EXPECT_NEAR(dGeomGetPosition(bob.getGeom())[0], SPHERE_X, TOLERANCE);
  EXPECT_NEAR(dGeomGetPosition(bob.getGeom())[1], Y, TOLERANCE);
}

TEST(Attach, RotatedCompositeKeepsWorldInertia) {
  World w;
  Box rod(w.world, w.space, 3.0, 0.1, 0.1, ROD_MASS);
  Sphere bob(w.world, w.space, RADIUS, SPHERE_MASS);
  // The rod is built turned 90 degrees about y (along -z) and the bob placed
  // at its end: the composite's world inertia must be the unrotated one turned.
  dMatrix3 R;
  dRFromAxisAndAngle(R, 0, 1, 0, M_PI / 2);
  dBodySetRotation(rod.getBody(), R);
  rod.setPosition(0, Y, -ROD_X);
  bob.setPosition(0, Y, -SPHERE_X);
  ASSERT_TRUE(bob.attach(rod));

  dMass m;
  dBodyGetMass(rod.getBody(), &m);
  const dReal* p = dBodyGetPosition(rod.getBody());
  EXPECT_NEAR(p[2], -centreX(), TOLERANCE);
  // World inertia = R I_body R^T.
  dMass world = m;
  dMassRotate(&world, dBodyGetRotation(rod.getBody()));
  double I[3][3];
  expectedInertia(I);
  // Turned about y, the long axis is z: xx and zz swap.
  EXPECT_NEAR(world.I[0], I[2][2], 1e-12);
  EXPECT_NEAR(world.I[5], I[1][1], 1e-12);
  EXPECT_NEAR(world.I[10], I[0][0], 1e-12);
  EXPECT_NEAR(dGeomGetPosition(bob.getGeom())[2], -SPHERE_X, TOLERANCE);
}

TEST(Attach, RefusesStaticGeoms) {
  World w;
  Box platform(w.world, w.space, 1, 1, 1, 1);
  Sphere ball(w.world, w.space, 0.5, 1);
  platform.setAsFixedGeom();
  EXPECT_TRUE(platform.isFixed());
  EXPECT_FALSE(ball.attach(platform));
  EXPECT_FALSE(ball.isFixed());
}

TEST(AbstractObject, DataIsStoredOnTheGeom) {
  World w;
  Sphere ball(w.world, w.space, 0.15, 1.0);
  const double bounce = 0.75;
  ball.setData(&bounce, sizeof bounce);
  EXPECT_EQ(*odelab::AbstractObject::dataOf<double>(ball.getGeom()), 0.75);
}

}  // namespace
