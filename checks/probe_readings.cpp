// A probe's figure against the exact figure of ODE's own integrator: a ball
// falling from rest under g at step h sits at y0 + g h^2 n (n + 1) / 2 after
// n steps (semi-implicit Euler: the velocity first, then the position), so
// a reading at a time between two steps, a largest and least reading in a
// window and a first crossing are known to rounding, as are a spinning
// body's angular momentum (I w about a principal axis) and the world's
// energy (the energy measure's). A probe that read the wrong step, or did
// not interpolate, is off by a share of a step's travel: far outside 1e-9.
#include <gtest/gtest.h>

#include <string>

#include "Metrics.h"
#include "world/WorldFileScene.h"
#include "world/WorldJson.h"

namespace {

using namespace odelab;

constexpr double H = 0.01, G = -10.0, Y0 = 100.0;

double fallen(int steps) { return Y0 + G * H * H * steps * (steps + 1) / 2.0; }

TEST(ProbeReadings, AreTheIntegratorsExactFigures) {
  const world::World w = world::worldFromJson(R"({"format": "odelab-world", "version": 1, "duration": 1.0,
    "settings": {"step": 0.01, "gravity": [0, -10, 0]},
    "bodies": [{"mass": 1, "inertia": [0.004, 0.004, 0.004, 0, 0, 0], "position": [0, 100, 0]},
               {"mass": 2, "inertia": [0.1, 0.2, 0.3, 0, 0, 0], "position": [5, 0, 0], "angular_velocity": [0, 3, 0],
                "gravity": false}],
    "geoms": [{"shape": "sphere", "body": 0, "radius": 0.1}, {"shape": "sphere", "body": 1, "radius": 0.1}],
    "surfaces": [{"mu": 0}],
    "measures": [{"kind": "energy"},
      {"kind": "probe", "name": "y_between", "body": 0, "of": "position", "axis": "y", "at": 0.505},
      {"kind": "probe", "name": "y_on_step", "body": 0, "of": "position", "axis": "y", "at": 0.5},
      {"kind": "probe", "name": "vy_last", "body": 0, "of": "velocity", "axis": "y"},
      {"kind": "probe", "name": "drop_last", "body": 0, "of": "displacement", "axis": "magnitude"},
      {"kind": "probe", "name": "lowest", "body": 0, "of": "position", "axis": "y", "take": "min", "until": 0.7},
      {"kind": "probe", "name": "highest_after", "body": 0, "of": "position", "axis": "y", "take": "max", "from": 0.2},
      {"kind": "probe", "name": "crossing", "body": 0, "of": "position", "axis": "y", "take": "first_crossing", "value": 99,
       "expect": 0.4422222222222222, "tolerance": 1e-9},
      {"kind": "probe", "name": "never", "body": 0, "of": "position", "axis": "y", "take": "first_crossing", "value": 200,
       "expect": 1, "tolerance": 1},
      {"kind": "probe", "name": "spin", "body": 1, "of": "angular_momentum", "axis": "magnitude"},
      {"kind": "probe", "name": "spin_rate", "body": 1, "of": "angular_velocity", "axis": "y", "at": 0.3},
      {"kind": "probe", "name": "y_at_end", "body": 0, "of": "position", "axis": "y", "at": 1.0},
      {"kind": "probe", "name": "world_energy", "of": "energy"}]})");
  world::WorldFileScene scene(w);
  RunOptions options;
  options.headless = true;
  scene.initialize(options);
  ASSERT_TRUE(scene.runFor(w.duration));
  const Metrics m = scene.metrics();
  scene.shutdown();
  ASSERT_EQ(m.get("steps"), 100.0);
  EXPECT_NEAR(m.get("y_between_value"), (fallen(50) + fallen(51)) / 2, 1e-9);  // halfway between steps 50 and 51
  EXPECT_NEAR(m.get("y_on_step_value"), fallen(50), 1e-9);
  EXPECT_NEAR(m.get("y_at_end_value"), fallen(100), 1e-9);  // the last step, its time a rounding off 1 s
  EXPECT_NEAR(m.get("vy_last_value"), G * 100 * H, 1e-9);
  EXPECT_NEAR(m.get("drop_last_value"), Y0 - fallen(100), 1e-9);
  EXPECT_NEAR(m.get("lowest_value"), fallen(70), 1e-9);         // the window ends at 0.7 s
  EXPECT_NEAR(m.get("highest_after_value"), fallen(20), 1e-9);  // the window starts at 0.2 s
  // y crosses 99 between steps 44 (99.01) and 45 (98.965): 0.44 + 0.01 (0.01 / 0.045) s.
  EXPECT_NEAR(m.get("crossing_value"), 0.44 + H * (fallen(44) - 99) / (fallen(44) - fallen(45)), 1e-9);
  EXPECT_EQ(m.get("crossing_within"), 1.0);
  EXPECT_NEAR(m.get("crossing_error"), m.get("crossing_value") - 0.4422222222222222, 1e-15);
  EXPECT_EQ(m.get("crossing_tolerance"), 1e-9);
  // A crossing that never came has no figure, and is not within any tolerance.
  EXPECT_FALSE(m.get("never_value") == m.get("never_value"));
  EXPECT_EQ(m.get("never_within"), 0.0);
  EXPECT_FALSE(m.has("spin_expected"));  // no expect: the figure alone
  EXPECT_NEAR(m.get("spin_value"), 0.2 * 3, 1e-9);
  EXPECT_NEAR(m.get("spin_rate_value"), 3, 1e-9);
  EXPECT_NEAR(m.get("world_energy_value"), m.get("energy_last_J"), 1e-9);
}

}  // namespace
