#include "MujocoLayout.h"

#include <deque>

namespace odelab::engines::mujoco {

namespace {

using world::Joint;
using world::JointKind;
using world::World;

bool alive(const World& world, int body) { return body < 0 || !world.bodies[static_cast<size_t>(body)].removed; }

// Fills the child's mount for `joint`, whose other side `parent` is placed
// (or the world): the MJCF pose relative to the parent and the joint's
// anchor and axis in the child's frame, all from the joint's reference.
void mountOnJoint(Mount& child, int childIndex, int parent, int jointIndex, const Joint& joint,
                  const JointFrames& frames) {
  const bool childIsBody1 = joint.body1 == childIndex;
  const Pose& childPose = childIsBody1 ? frames.body1 : frames.body2;
  const Pose& parentPose = childIsBody1 ? frames.body2 : frames.body1;
  child.kind = Mount::Kind::Joint;
  child.parent = parent;
  child.joint = jointIndex;
  child.reference = compose(inverse(parentPose), childPose);
  child.anchor = pointIn(childPose, joint.anchor);
  // ODE's hinge angle and slider position are body1's relative to body2;
  // MuJoCo's are the child's relative to its parent: where the child is
  // body2 the axis turns round, so that the stops keep their meaning.
  const Vec3 axis = rotate(conj(childPose.orientation), joint.axis);
  const double length = norm(axis);
  child.axis = scale(axis, (childIsBody1 ? 1.0 : -1.0) / (length > 0 ? length : 1.0));
}

}  // namespace

Layout planLayout(const World& world, const std::vector<Pose>& references, const std::vector<JointFrames>& frames) {
  const int bodyCount = static_cast<int>(world.bodies.size());
  const int jointCount = static_cast<int>(world.joints.size());
  Layout layout;
  layout.bodies.resize(static_cast<size_t>(bodyCount));
  layout.children.resize(static_cast<size_t>(bodyCount));
  std::vector<bool> placed(static_cast<size_t>(bodyCount), false), used(static_cast<size_t>(jointCount), false);
  std::deque<int> queue;

  auto movable = [&](int body) { return body >= 0 && alive(world, body) && !world.bodies[static_cast<size_t>(body)].kinematic; };
  auto place = [&](int body, const Mount& mount) {
    layout.bodies[static_cast<size_t>(body)] = mount;
    placed[static_cast<size_t>(body)] = true;
    if (mount.parent < 0) layout.roots.push_back(body);
    else layout.children[static_cast<size_t>(mount.parent)].push_back(body);
    layout.order.push_back(body);
    queue.push_back(body);
  };
  // A placed body's unplaced neighbours become its children, breadth first.
  auto grow = [&]() {
    while (!queue.empty()) {
      const int parent = queue.front();
      queue.pop_front();
      if (layout.bodies[static_cast<size_t>(parent)].kind == Mount::Kind::Mocap) continue;
      for (int j = 0; j < jointCount; ++j) {
        const Joint& joint = world.joints[static_cast<size_t>(j)];
        if (used[static_cast<size_t>(j)] || (joint.body1 != parent && joint.body2 != parent)) continue;
        const int child = joint.body1 == parent ? joint.body2 : joint.body1;
        if (!movable(child) || placed[static_cast<size_t>(child)]) continue;
        Mount mount;
        mountOnJoint(mount, child, parent, j, joint, frames[static_cast<size_t>(j)]);
        mount.depth = layout.bodies[static_cast<size_t>(parent)].depth + 1;
        used[static_cast<size_t>(j)] = true;
        place(child, mount);
      }
    }
  };

  // Kinematic bodies are MuJoCo's mocap bodies: children of the world
  // without joints, moved by the adapter.
  for (int b = 0; b < bodyCount; ++b)
    if (alive(world, b) && world.bodies[static_cast<size_t>(b)].kinematic) {
      Mount mount;
      mount.kind = Mount::Kind::Mocap;
      mount.reference = references[static_cast<size_t>(b)];
      place(b, mount);
    }
  queue.clear();
  // A body jointed to the world hangs from it on its first such joint.
  for (int j = 0; j < jointCount; ++j) {
    const Joint& joint = world.joints[static_cast<size_t>(j)];
    if (joint.body1 >= 0 && joint.body2 >= 0) continue;
    const int body = joint.body1 >= 0 ? joint.body1 : joint.body2;
    if (!movable(body) || placed[static_cast<size_t>(body)]) continue;
    Mount mount;
    mountOnJoint(mount, body, -1, j, joint, frames[static_cast<size_t>(j)]);
    used[static_cast<size_t>(j)] = true;
    place(body, mount);
  }
  grow();
  // Every body still unplaced is free, and its jointed neighbours its children.
  for (int b = 0; b < bodyCount; ++b)
    if (movable(b) && !placed[static_cast<size_t>(b)]) {
      Mount mount;
      mount.kind = Mount::Kind::Free;
      mount.reference = references[static_cast<size_t>(b)];
      place(b, mount);
      grow();
    }
  for (int j = 0; j < jointCount; ++j) {
    const Joint& joint = world.joints[static_cast<size_t>(j)];
    if (!used[static_cast<size_t>(j)] && alive(world, joint.body1) && alive(world, joint.body2)) layout.loops.push_back(j);
  }
  return layout;
}

}  // namespace odelab::engines::mujoco
