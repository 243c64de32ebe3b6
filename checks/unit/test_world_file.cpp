// The world file (doc/world-format.md): what is written reads back the same,
// and what is wrong is refused naming the field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "world/WorldJson.h"
#include "world_file_error_of.h"

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

std::string errorOf(const std::string& text) { return worldFileErrorOf(text); }

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
  EXPECT_NE(errorOf("{\"format\": \"odelab-world\", \"version\": 2}").find("version"), std::string::npos);
  EXPECT_NE(errorOf(withField("\"bodys\": []")).find("bodys: is not a field"), std::string::npos);
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
  EXPECT_NE(errorOf(worldToJson(lonely)).find("bodies[2]: has no geom"), std::string::npos);
}

TEST(WorldFile, MeasuresAndEventsReadBackTheSame) {
  World w = twoBodies();
  w.joints.clear();
  Measure energy;
  energy.kind = MeasureKind::Energy;
  energy.scale = 12.5;
  Measure swing;
  swing.kind = MeasureKind::Period;
  swing.body = 0;
  swing.name = "swing";
  swing.axis = 2;
  swing.about = 0.25;
  swing.expected = 2.0;
  Measure wall;
  wall.kind = MeasureKind::Tunnelling;
  wall.geom = 0;
  w.measures = {energy, swing, wall};
  Event drop;
  drop.at = 0.5;
  drop.body = 1;
  Event push;
  push.at = 1.0;
  push.kind = EventKind::Push;
  push.body = 1;
  push.impulse = {1, 0, -2};
  w.events = {drop, push};
  const std::string once = worldToJson(w);
  EXPECT_EQ(worldToJson(worldFromJson(once)), once);
}

TEST(WorldFile, ErrorsNameTheLine) {
  const std::string text = worldToJson(twoBodies());
  const std::string mass = "\"mass\": 2.5";
  const std::size_t at = text.find(mass);
  const std::string line = std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  EXPECT_NE(errorOf(std::string(text).replace(at, mass.size(), "\"mass\": 0")).find("line " + line + ": bodies[0].mass"),
            std::string::npos);
  EXPECT_NE(errorOf("{\n\"format\": \"odelab-world\",\n \"version\": 1,\n\"x\": [1e999]}").find("(line 4)"),
            std::string::npos);
}

TEST(WorldFile, PhysicalRefusals) {
  World skewed = twoBodies();
  skewed.bodies[0].inertia = {1, 1, 1, 5, 0, 0};  // every diagonal > 0, and still no real body's
  EXPECT_NE(errorOf(worldToJson(skewed)).find("bodies[0].inertia: is not positive definite"), std::string::npos);
  World tilted = twoBodies();
  tilted.geoms[0].plane = {0, 2, 0, 0};
  EXPECT_NE(errorOf(worldToJson(tilted)).find("geoms[0].plane: (a, b, c) must be a unit normal"), std::string::npos);
  std::string text = worldToJson(twoBodies());
  const std::string body = "\"body\": 1";
  // 2^64 - 1 would wrap to -1 (the static world) in a signed read.
  EXPECT_NE(errorOf(text.replace(text.find(body), body.size(), "\"body\": 18446744073709551615")).find("geoms[2].body: must be in"),
            std::string::npos);
  World jointed = twoBodies();
  Event drop;
  drop.at = 1;
  drop.body = 0;  // hinged to the world
  jointed.events = {drop};
  EXPECT_NE(errorOf(worldToJson(jointed)).find("events[0].drop: body 0 has a joint"), std::string::npos);
}
