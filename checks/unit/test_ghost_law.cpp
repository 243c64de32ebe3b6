// A world's ghost follows its law's closed form at every time asked, from the
// world's own figures (world/GhostLaw.h): the ballistic arc, the bounce off
// the ground with the surface's restitution (its impacts' times and speeds,
// rest after the last), the small-angle pendulum. Each expected figure is
// worked by hand in its comment from the world's start state; the
// tolerances are far below a millimetre, what a window could show.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "world/GhostLaw.h"
#include "world/WorldJson.h"

namespace {

using namespace odelab::world;

constexpr double G = 9.81;
constexpr double METRE = 1e-9;   // m: the closed form against the law's arithmetic
constexpr double SECOND = 1e-9;  // s

// A ball of radius 0.1 m on a ground y = -0.1 (so its centre is at y = 0 in
// contact), `at` its centre, `velocity` its start velocity, the ground's
// surface `surface`.
World ball(const std::string& at, const std::string& velocity, const std::string& surface, const std::string& law) {
  return worldFromJson(R"({"format": "odelab-world", "version": 1,
    "settings": {"step": 0.001, "gravity": [0, -9.81, 0]},
    "bodies": [{"mass": 1, "inertia": [0.004, 0.004, 0.004, 0, 0, 0], "position": )" + at +
                       R"(, "linear_velocity": )" + velocity + R"(}],
    "geoms": [{"shape": "sphere", "body": 0, "radius": 0.1}, {"shape": "plane", "body": -1, "plane": [0, 1, 0, -0.1]}],
    "surfaces": [)" + surface + R"(], "ghost": {"body": 0, "law": ")" + law + R"("}})");
}

// Dropped from h = v^2/(2g) above contact, it meets the ground at v.
std::string dropFor(double v) {
  char at[64];
  std::snprintf(at, sizeof at, "[0, %.17g, 0]", v * v / (2 * G));
  return at;
}

TEST(GhostLaw, BallisticArcIsTheClosedForm) {
  // The atlas's projectile: from (0, 1, 0) at (3, 4, 0) m/s. Apex at t = 4/g
  // = 0.407747 s, y = 1 + 16/(2g) = 1.815494 m; at 1 s, x = 3, y = 1 + 4 - g/2 = 0.095.
  const World w = ball("[0, 1, 0]", "[3, 4, 0]", R"({"mu": 0})", "ballistic");
  const GhostMotion ghost(w);
  EXPECT_NEAR(ghost.at(0.0).position[1], 1.0, METRE);
  EXPECT_NEAR(ghost.at(4 / G).position[1], 1.0 + 16 / (2 * G), METRE);
  EXPECT_NEAR(ghost.at(4 / G).position[0], 12 / G, METRE);
  EXPECT_NEAR(ghost.at(1.0).position[0], 3.0, METRE);
  EXPECT_NEAR(ghost.at(1.0).position[1], 0.095, METRE);
  // No contact: past the ground it goes on falling (t = 2 s: 1 + 8 - 2g = -10.62).
  EXPECT_NEAR(ghost.at(2.0).position[1], -10.62, METRE);
  EXPECT_TRUE(ghost.impacts(2.0).empty());
  EXPECT_NE(ghost.legend().find("ballistic"), std::string::npos) << ghost.legend();
}

TEST(GhostLaw, BounceAtFiveMetresASecondWithHalfRestitution) {
  // bounce-v5-e0p5: h = 25/(2g) = 1.274210 m; impact at t1 = 5/g = 0.509684 s
  // at 5 m/s; up at e v = 2.5 m/s to e^2 h = 0.318552 m at t1 + 2.5/g =
  // 0.764526 s; the next impact at t1 + 5/g = 1.019368 s at 2.5 m/s.
  const World w = ball(dropFor(5), "[0, 0, 0]", R"({"mu": 0, "restitution": 0.5})", "bounce");
  const GhostMotion ghost(w);
  const double t1 = 5 / G;
  // Falling: t = 0.25 s, y = h - g 0.25^2/2 = 1.274210 - 0.306563 = 0.967647.
  EXPECT_NEAR(ghost.at(0.25).position[1], 25 / (2 * G) - G * 0.0625 / 2, METRE);
  EXPECT_NEAR(ghost.at(0.25).position[1], 0.967647, 1e-6);
  EXPECT_NEAR(ghost.at(t1).position[1], 0.0, METRE);
  // After the first bounce: the apex, then t = 0.9 s (0.390316 s into the
  // flight: 2.5 s - g s^2/2 = 0.975790 - 0.747260 = 0.228530 m).
  EXPECT_NEAR(ghost.at(t1 + 2.5 / G).position[1], 0.318552, 1e-6);
  EXPECT_NEAR(ghost.at(0.9).position[1], 2.5 * (0.9 - t1) - G * (0.9 - t1) * (0.9 - t1) / 2, METRE);
  EXPECT_NEAR(ghost.at(0.9).position[1], 0.228530, 1e-6);
  EXPECT_NEAR(ghost.at(0.9).position[0], 0.0, METRE);
  const std::vector<GhostImpact> impacts = ghost.impacts(1.1);
  ASSERT_EQ(impacts.size(), 2u);
  EXPECT_NEAR(impacts[0].time, 0.509684, 1e-6);
  EXPECT_NEAR(impacts[0].speed, 5.0, 1e-9);
  EXPECT_NEAR(impacts[1].time, 1.019368, 1e-6);
  EXPECT_NEAR(impacts[1].speed, 2.5, 1e-9);
  // The flights shrink by e: all of them end by t1 + 2 e v/(g (1 - e)) =
  // 1.529052 s, after which the ball rests in contact.
  EXPECT_NEAR(ghost.at(1.6).position[1], 0.0, METRE);
  EXPECT_NEAR(ghost.at(100.0).position[1], 0.0, METRE);
  EXPECT_NE(ghost.legend().find("e = 0.5"), std::string::npos) << ghost.legend();
}

TEST(GhostLaw, ElasticBounceRepeatsEveryFlight) {
  // e = 1 from 5 m/s: every flight lasts 2 v/g = 1.019368 s; 0.1 s into the
  // fourth flight after the first impact, y = 0.5 - g 0.01/2 = 0.45095.
  const World w = ball(dropFor(5), "[0, 0, 0]", R"({"mu": 0, "restitution": 1})", "bounce");
  const GhostMotion ghost(w);
  const double t = 5 / G + 3 * (10 / G) + 0.1;
  EXPECT_NEAR(ghost.at(t).position[1], 0.45095, 1e-6);
  EXPECT_EQ(ghost.impacts(t).size(), 4u);
}

TEST(GhostLaw, BounceThrownUpwardsAndTheSurfacesOwnLimits) {
  // Thrown up at 3 m/s from 1 m above contact: it lands at v = sqrt(9 + 2g)
  // = 5.357238 m/s, at t = (3 + 5.357238)/g = 0.851910 s.
  const World up = ball("[0, 1, 0]", "[0, 3, 0]", R"({"mu": 0, "restitution": 0.5})", "bounce");
  const std::vector<GhostImpact> first = GhostMotion(up).impacts(0.9);
  ASSERT_EQ(first.size(), 1u);
  EXPECT_NEAR(first[0].speed, std::sqrt(9 + 2 * G), 1e-9);
  EXPECT_NEAR(first[0].time, (3 + std::sqrt(9 + 2 * G)) / G, SECOND);
  // No restitution stated: ODE's contact keeps the ball down after its impact.
  const GhostMotion dead(ball(dropFor(5), "[0, 0, 0]", R"({"mu": 0})", "bounce"));
  EXPECT_NEAR(dead.at(5 / G + 0.2).position[1], 0.0, METRE);
  // An impact slower than the surface's bounce_velocity does not bounce.
  const GhostMotion slow(ball(dropFor(5), "[0, 0, 0]", R"({"mu": 0, "restitution": 0.5, "bounce_velocity": 6})", "bounce"));
  EXPECT_NEAR(slow.at(5 / G + 0.2).position[1], 0.0, METRE);
  EXPECT_EQ(slow.impacts(2.0).size(), 1u);
}

TEST(GhostLaw, SmallAnglePendulumSwingsToTheOtherSideInHalfAPeriod) {
  // The atlas's 5-degree pendulum: a ball (inertia 0.001 kg m^2) 1 m below a
  // ball joint at (0, 2, 0), at 5 degrees. About the pivot I = 0.001 + 1, so
  // the small-angle period is 2 pi sqrt(I/(m g d)) = 2.007070 s; at T/4 it
  // is below the pivot, at T/2 at -5 degrees, at T back where it started.
  const World w = worldFromJson(R"({"format": "odelab-world", "version": 1,
    "settings": {"step": 0.001, "gravity": [0, -9.81, 0]},
    "bodies": [{"mass": 1, "inertia": [0.001, 0.001, 0.001, 0, 0, 0],
                "position": [0.08715574274765817, 1.0038053019082545, 0]}],
    "geoms": [{"shape": "sphere", "body": 0, "radius": 0.05, "collide": 0}],
    "joints": [{"type": "ball", "body1": 0, "body2": -1, "anchor": [0, 2, 0]}],
    "surfaces": [{"mu": 0}], "ghost": {"body": 0, "law": "pendulum"}})");
  const GhostMotion ghost(w);
  const double period = 2 * 3.14159265358979323846 * std::sqrt(1.001 / G);
  EXPECT_NEAR(period, 2.007070, 1e-6);
  EXPECT_NEAR(ghost.at(period / 4).position[0], 0.0, METRE);
  EXPECT_NEAR(ghost.at(period / 4).position[1], 1.0, METRE);
  EXPECT_NEAR(ghost.at(period / 2).position[0], -0.08715574274765817, METRE);
  EXPECT_NEAR(ghost.at(period / 2).position[1], 1.0038053019082545, METRE);
  EXPECT_NEAR(ghost.at(period).position[0], 0.08715574274765817, METRE);
  EXPECT_NE(ghost.legend().find("2.00707"), std::string::npos) << ghost.legend();
}

TEST(GhostLaw, ThePoseIsAFunctionOfTimeAlone) {
  // A rewind asks for an earlier time after a later one: the same answer.
  const GhostMotion ghost(ball(dropFor(5), "[0, 0, 0]", R"({"mu": 0, "restitution": 0.5})", "bounce"));
  const double before = ghost.at(0.9).position[1];
  ghost.at(3.0);
  EXPECT_EQ(ghost.at(0.9).position[1], before);
  EXPECT_EQ(ghost.at(0.0).position[1], ghost.at(-1.0).position[1]);  // before the start: the start
}

}  // namespace
