// The world file (doc/world-format.md): what is written reads back the same,
// and what is wrong is refused naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "world/WorldJson.h"

namespace {

using namespace odelab::world;

World twoBodies() {
  World w;
  w.scene = "made here";
  w.settings.step = 0.0005;
  w.settings.gravity = {0, -9.823, 0};
  Body ball;
  ball.mass = 2.5;
  ball.inertia = {0.1, 0.2, 0.3, 0.01, 0.02, 0.03};
  ball.position = {1, 2, 3};
  ball.orientation = {0.5, 0.5, 0.5, 0.5};
  ball.linearVelocity = {0.1, -1e-300, 7};
  ball.maxAngularSpeed = 10;
  ball.autoDisable.on = true;
  Body box;
  box.kinematic = true;
  w.bodies = {ball, box};
  Geom plane;
  plane.shape = ShapeKind::Plane;
  Geom sphere;
  sphere.shape = ShapeKind::Sphere;
  sphere.size = {0.25, 0, 0};
  sphere.body = 0;
  Geom cube;
  cube.body = 1;
  cube.position = {0, 0.5, 0};
  cube.collide = 2;
  w.geoms = {plane, sphere, cube};
  Joint hinge;
  hinge.kind = JointKind::Hinge;
  hinge.body1 = 0;
  hinge.anchor = {0, 7, 0};
  hinge.lowStop = -1;
  hinge.cfm = 1e-5;
  w.joints = {hinge};
  Surface bouncy;
  bouncy.bounce = true;
  bouncy.restitution = 0.5;
  bouncy.bounceVelocity = 0.01;
  Surface sticky;  // infinite friction
  w.surfaces = {bouncy, sticky};
  w.defaultSurface = 0;
  w.pairSurfaces = {{0, 2, 1}};
  return w;
}

std::string errorOf(const std::string& text) {
  try {
    worldFromJson(text);
  } catch (const WorldFileError& error) {
    return error.what();
  }
  return "(accepted)";
}

std::string withField(const std::string& field) {
  std::string text = worldToJson(twoBodies());
  return text.insert(text.find('{') + 1, field + ",");
}

}  // namespace

TEST(WorldFile, WhatIsWrittenReadsBackTheSame) {
  const std::string once = worldToJson(twoBodies());
  const World back = worldFromJson(once);
  EXPECT_EQ(worldToJson(back), once);
  EXPECT_EQ(back.bodies[0].linearVelocity[1], -1e-300);  // every digit of a double survives
  EXPECT_TRUE(std::isinf(back.surfaces[1].mu));
  EXPECT_EQ(back.surfaceBetween(2, 0).mu, back.surfaces[1].mu);
  EXPECT_TRUE(back.surfaces[back.surfaceBetween(0, 1) == back.surfaces[0] ? 0 : 1].bounce);
}

TEST(WorldFile, TouchingFollowsBodiesJointsAndBits) {
  World w = twoBodies();
  EXPECT_TRUE(w.mayTouch(0, 1));   // the plane and the sphere
  EXPECT_TRUE(w.mayTouch(0, 2));   // the plane (all bits) and the cube (collide 2)
  w.geoms[0].category = 1;
  w.geoms[0].collide = 0;
  EXPECT_FALSE(w.mayTouch(0, 2));  // neither's category meets the other's collide bits (ODE's rule)
  Joint ball;
  ball.body1 = 0;
  ball.body2 = 1;
  w.joints.push_back(ball);
  EXPECT_FALSE(w.mayTouch(1, 2));  // joined bodies never touch
}

TEST(WorldFile, RefusalsNameTheField) {
  EXPECT_NE(errorOf("{").find("not JSON"), std::string::npos);
  EXPECT_NE(errorOf("{\"format\": \"odelab-world\", \"version\": 2}").find("world.version"), std::string::npos);
  EXPECT_NE(errorOf(withField("\"bodys\": []")).find("world.bodys: is not a field"), std::string::npos);
  std::string text = worldToJson(twoBodies());
  const std::string mass = "\"mass\": 2.5";
  EXPECT_NE(errorOf(std::string(text).replace(text.find(mass), mass.size(), "\"mass\": -1")).find("bodies[0].mass: must be in"),
            std::string::npos);
  const std::string body = "\"body\": 1";
  EXPECT_NE(errorOf(std::string(text).replace(text.find(body), body.size(), "\"body\": 5")).find("geoms[2].body: must be in [-1, 1]"),
            std::string::npos);
  World turned = twoBodies();
  turned.bodies[0].orientation = {1, 1, 0, 0};
  EXPECT_NE(errorOf(worldToJson(turned)).find("bodies[0].orientation: must be a unit quaternion"), std::string::npos);
  World lonely = twoBodies();
  lonely.bodies.push_back(Body{});
  EXPECT_NE(errorOf(worldToJson(lonely)).find("bodies[2]: has no geom and no joint"), std::string::npos);
}
