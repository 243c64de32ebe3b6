#pragma once

// The ranges of a world file's numbers (doc/world-format.md) that are not
// world settings (those are the knobs' own, utils/WorldSettings.h's
// ranges::): one table that the reader (WorldJson.cpp) enforces,
// doc/world.schema.json states (checks/scripts/world_schema_ranges.py
// compares the two through rangesAsJson) and the writer stays within (it
// writes what ODE holds, and ODE was given what the reader allowed).
// Each bound keeps ODE's arithmetic finite and its hash space's cells
// countable: it numbers cells of 1/8 m in an int, so a coordinate past about
// 2.7e8 m fails its own check (random worlds at 1e9 m found it); 1e6 m leaves
// a margin of hundreds for what moves during a run.

#include <cstddef>
#include <string>

namespace odelab::world::limits {

constexpr double LENGTH = 1e6;          // m: |x|, |y|, |z| of a position, anchor, offset; a plane's offset
constexpr double SIDE_MIN = 1e-9;       // m: a box's side, a radius (a length may be 0)
constexpr double SIDE_MAX = 1e6;        // m
constexpr double SPEED = 1e6;           // m/s: each component of a linear velocity
constexpr double ANGULAR_SPEED = 1e6;   // rad/s: each component of an angular velocity
constexpr double MASS_MIN = 1e-12;      // kg
constexpr double MASS_MAX = 1e15;       // kg
constexpr double INERTIA = 1e27;        // kg m^2: |each entry| (MASS_MAX at LENGTH's reach)
constexpr double IMPULSE = 1e21;        // N s: each component (MASS_MAX at SPEED)
constexpr double GRAVITY_COMPONENT = 100.0;  // m/s^2: each component; the magnitude is ranges::GRAVITY's
// A probe's numbers (doc/world-format.md, "probe"). Times: a world's
// duration, a probe's `at`, `from` and `until`, within a run of TIME; the
// shortest duration is one step at the smallest step. A reading and its
// expected value or tolerance: at most READING in its unit, the largest a
// body's state gives (angular momentum, INERTIA at ANGULAR_SPEED).
constexpr double TIME = 1e6;            // s
constexpr double DURATION_MIN = 1e-6;   // s: ranges::STEP's smallest
constexpr double READING = 1e33;        // m, m/s, rad/s, kg m^2/s, s
constexpr double RELATIVE_TOLERANCE = 1.0;  // a fraction of |expect|: past 1 no figure is checked
constexpr std::size_t ITEMS = 1000000;  // items in one list (bodies, geoms, ...): more than 64 MiB could hold
constexpr std::size_t BYTES = 64u << 20;  // a world file's size

// Every bound above and the settings' ranges, as JSON {"name": [low, high]}:
// what the schema check reads.
std::string rangesAsJson();

}  // namespace odelab::world::limits
