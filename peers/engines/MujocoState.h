#pragma once

// A body's world state (centre of mass, orientation, velocities) to and from
// MuJoCo's coordinates: a free body's are its state itself; a body hanging
// on a joint has only its joint's angle or position (and rate) relative to
// its parent, so its state is read from MuJoCo's forward kinematics and set
// as the joint coordinates that come closest.

#include <mujoco/mujoco.h>

#include <vector>

#include "MujocoLayout.h"
#include "world/Engine.h"

namespace odelab::engines::mujoco {

// Poses and velocities of every body from qpos and qvel (what mj_step
// leaves stale: it integrates after computing them).
void refreshKinematics(const mjModel* m, mjData* d);

// Needs refreshKinematics since the last change. The body's frame is its
// centre of mass (the MJCF puts the inertia at its origin).
world::BodyState readBody(const mjModel* m, const mjData* d, int mjBody);

// The body's joint coordinates for the world state `desired`, with its
// parent (mjParent, 0: the world) as MuJoCo holds it now (refreshed).
void writeJointCoordinates(const mjModel* m, mjData* d, const Mount& mount, world::JointKind kind, int mjBody,
                           int mjParent, const world::BodyState& desired);

// A free body's coordinates: exactly its state.
void writeFreeBody(const mjModel* m, mjData* d, int mjBody, const world::BodyState& desired);

// The body's own joint coordinates (qpos, qvel), as they are, to be copied
// into a rebuilt model whose body sits on the same joint.
struct Coordinates {
  std::vector<double> qpos, qvel;
};
Coordinates coordinatesOf(const mjModel* m, const mjData* d, int mjBody);
void setCoordinates(const mjModel* m, mjData* d, int mjBody, const Coordinates& c);

}  // namespace odelab::engines::mujoco
