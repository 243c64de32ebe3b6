#pragma once

// ODE's contact surfaces (dSurfaceParameters) in MuJoCo's terms: a friction
// coefficient, the contact's dimension, and its softness (solref, solimp).

#include <set>
#include <string>
#include <vector>

#include "world/Engine.h"

namespace odelab::engines::mujoco {

// Best: the stiffest contact MuJoCo accepts at a step h (a time constant of
// 2 steps, its safe minimum; the default is 0.02 s), critically damped, with
// an impedance near 1, so that less of the load is let through as overlap.
// Measured on the old mujoco_lab's stack, wall and domino scenes.
constexpr double BEST_TIME_CONSTANT_STEPS = 2.0;
constexpr const char* BEST_SOLIMP = "0.99 0.999 0.001";

// Best for a bouncing surface: MuJoCo has no restitution coefficient; its
// documented way to a bouncy contact is a negative solref "-k -b", a spring
// of stiffness k (acceleration per metre of overlap) with damping b. k = 5e3
// /s^2 lasts pi / sqrt(5e3) = 44 ms; stiffer springs (2e4, 1e5) were measured
// less accurate at step 0.001 in the old mujoco_lab (apex error after 20
// bounces 5e-3 and 8e-3 against 1.7e-4): fewer steps per contact.
constexpr double BOUNCE_STIFFNESS = 5e3;

struct ContactParams {
  int condim = 3;       // 1: frictionless, 3: sliding friction (ODE has no torsional or rolling friction)
  double mu = 1.0;      // sliding friction
  std::string solref;   // "" : MuJoCo's own
  std::string solimp;   // "" : MuJoCo's own
};

// What the surfaces of a world could not carry, gathered so that each
// fact is said once however many surfaces share it.
struct SurfaceLosses {
  bool infiniteFriction = false;
  std::set<double> forceBounds;      // mu without friction_pyramid
  std::set<double> restitutions;     // bouncing surfaces
  std::set<double> bounceVelocities; // their thresholds (Best: not applied)
  bool softness = false;             // a surface's own ERP or CFM
};

// The surface's contact; what it could not carry is added to `losses`.
ContactParams contactOf(const world::Surface& surface, world::EngineSetting setting, double step,
                        SurfaceLosses& losses);

// The losses as translation notes.
std::vector<std::string> notesOf(const SurfaceLosses& losses, world::EngineSetting setting);

// Whether the surface bounces at all (restitution above 0).
bool bounces(const world::Surface& surface);

// The 5 numbers of an MJCF friction attribute for a pair, the 3 of a geom.
std::string pairFriction(double mu);
std::string geomFriction(double mu);

// A number as MJCF text, exact (17 significant digits).
std::string num(double value);

}  // namespace odelab::engines::mujoco
