#pragma once

// Where each body of a world sits in MuJoCo's kinematic tree. MuJoCo holds
// joints in generalized coordinates: a joint is a body's degrees of freedom
// relative to its parent body, so every body has one parent (the world or
// another body) and the joints of a world must form a forest. A body jointed
// to the world hangs from the world on that joint; a body jointed to a
// placed body becomes its child on that joint; any other body is free (six
// degrees of freedom). A joint that would close a loop is left to an
// equality constraint (MujocoModel.cpp).

#include <vector>

#include "MujocoMath.h"
#include "world/WorldDescription.h"

namespace odelab::engines::mujoco {

// The two bodies' world poses when a joint was first seen (the static
// world's is the identity): its reference, where its angle or position is 0.
struct JointFrames {
  Pose body1, body2;
};

struct Mount {
  enum class Kind { Removed, Free, Mocap, Joint };
  Kind kind = Kind::Removed;
  int parent = -1;  // the parent body's index, or -1: the world
  int joint = -1;   // Kind::Joint: the joint (world.joints) to the parent
  int depth = 0;    // 0: a child of the world
  // The body's pose relative to its parent at the joint's reference (for a
  // root: in the world), as the MJCF places it.
  Pose reference;
  // Kind::Joint, in the body's own frame: the anchor (ball, hinge) and the
  // axis (hinge, slider), turned so that MuJoCo's coordinate of the child
  // relative to the parent equals ODE's of body1 relative to body2.
  Vec3 anchor{0, 0, 0};
  Vec3 axis{0, 0, 1};
};

struct Layout {
  std::vector<Mount> bodies;              // per world body
  std::vector<std::vector<int>> children; // per world body
  std::vector<int> roots;                 // the world's children
  std::vector<int> order;                 // every live body, each parent before its children
  std::vector<int> loops;                 // joints left to equality constraints
};

// `references`: each body's pose when first seen; `frames`: per joint.
Layout planLayout(const world::World& world, const std::vector<Pose>& references,
                  const std::vector<JointFrames>& frames);

}  // namespace odelab::engines::mujoco
