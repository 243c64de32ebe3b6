#pragma once

// A world's ghost (doc/world-format.md, "ghost"): the analytic motion of one
// body, as a pure function of simulated time, so that the window can draw it
// beside every engine's body and a rewind or a reset puts it right at once.
// Physics side only: the window draws the pose this gives
// (utils/render/GhostDraw.h). Every figure comes from the world: the body's
// start state, the gravity, the ground plane and the surface it meets it with.

#include <string>
#include <vector>

#include "WorldDescription.h"

namespace odelab::world {

// Why a world's ghost cannot follow its law: the ghost's field at fault
// ("body", "law") and the reason; `field` empty when it can.
struct GhostRefusal {
  std::string field;
  std::string reason;
};
GhostRefusal ghostRefusal(const World& world);

struct GhostPose {
  Vec3 position;    // the body's centre of mass
  Quat orientation; // the start orientation, turned by the law (pendulum); the others hold it
};

// The bounce law's impacts: when the ball meets the ground and how fast.
struct GhostImpact {
  double time;   // s
  double speed;  // m/s, towards the ground
};

class GhostMotion {
 public:
  // `world.ghost.on`, and ghostRefusal(world) found nothing wrong.
  explicit GhostMotion(const World& world);
  GhostPose at(double time) const;
  // Bounce: the impacts up to `until` (the ball at rest after the last, if
  // the law brings it to rest); the other laws have none.
  std::vector<GhostImpact> impacts(double until) const;
  // What the ghost is, for the HUD: "ghost: analytic ballistic arc".
  std::string legend() const;
  // The body's geoms, each posed relative to the body's centre of mass: what
  // the window outlines at the ghost's pose.
  const std::vector<Geom>& shapes() const { return shapes_; }

 private:
  // Bounce: the height above contact and the flight it is in at `time`.
  double bounceHeight(double time, std::vector<GhostImpact>* impacts) const;

  GhostLaw law_;
  std::vector<Geom> shapes_;
  Vec3 start_;
  Quat orientation_;
  Vec3 velocity_;
  Vec3 gravity_;          // what acts on the body (none when it has no gravity)
  // Bounce: the ground's normal, the height above contact and the speed along
  // the normal at the start, |g|, the restitution and the slowest impact that bounces.
  Vec3 normal_{0, 1, 0};
  double height_ = 0, rise_ = 0, g_ = 0, restitution_ = 0, bounceVelocity_ = 0;
  // Pendulum: the pivot, the axis, the angle from hanging and its rate at the
  // start, the small-angle angular frequency.
  Vec3 pivot_{0, 0, 0}, axis_{0, 0, 1};
  double angle_ = 0, angleRate_ = 0, frequency_ = 0;
};

}  // namespace odelab::world
