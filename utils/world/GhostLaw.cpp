#include "GhostLaw.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace odelab::world {

namespace {

constexpr double PI = 3.14159265358979323846;
// How far from parallel (as a sine) gravity may be from the ground's normal,
// or a start velocity from vertical, and still be the one-dimensional law:
// what a file's 17 digits hold, far below what a window shows.
constexpr double PARALLEL = 1e-9;
// A bounce this short (s) ends the law's flights: the ball is at rest. With
// e < 1 the flights shrink geometrically, so a finite number of them remain
// above it; the cap guards e so close to 1 that they would be millions.
constexpr double SHORTEST_FLIGHT = 1e-12;
constexpr long MOST_FLIGHTS = 1000000;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
Vec3 plus(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
// `a` less its part along unit `n`.
Vec3 across(const Vec3& a, const Vec3& n) { return minus(a, scaled(n, dot(a, n))); }

Quat product(const Quat& a, const Quat& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}
Quat turn(const Vec3& axis, double angle) {
  const double s = std::sin(angle / 2);
  return {std::cos(angle / 2), axis[0] * s, axis[1] * s, axis[2] * s};
}
// `v` turned by unit quaternion `q`.
Vec3 rotated(const Quat& q, const Vec3& v) {
  const Quat p = product(product(q, {0, v[0], v[1], v[2]}), {q[0], -q[1], -q[2], -q[3]});
  return {p[1], p[2], p[3]};
}

// The body's moment of inertia about world axis `a` through its centre of mass.
double inertiaAbout(const Body& b, const Vec3& a) {
  const Quat back{b.orientation[0], -b.orientation[1], -b.orientation[2], -b.orientation[3]};
  const Vec3 l = rotated(back, a);  // the axis in the body's frame
  const auto& i = b.inertia;        // xx, yy, zz, xy, xz, yz
  return i[0] * l[0] * l[0] + i[1] * l[1] * l[1] + i[2] * l[2] * l[2] +
         2 * (i[3] * l[0] * l[1] + i[4] * l[0] * l[2] + i[5] * l[1] * l[2]);
}

std::string number(double v) {
  std::ostringstream text;
  text.precision(6);
  text << v;
  return text.str();
}

// The world's one static plane, or -1 (none, or more than one: which ground?).
int groundPlane(const World& w, std::string& why) {
  int found = -1;
  for (size_t g = 0; g < w.geoms.size(); ++g)
    if (w.geoms[g].shape == ShapeKind::Plane) {
      if (found >= 0) {
        why = "the world has more than one plane (geoms[" + std::to_string(found) + "] and geoms[" + std::to_string(g) +
              "]): the law needs one ground";
        return -1;
      }
      found = static_cast<int>(g);
    }
  if (found < 0) why = "the world has no plane to bounce off";
  return found;
}

// The body's one geom, or -1 when it has several.
int onlyGeomOf(const World& w, int body) {
  int found = -1;
  for (size_t g = 0; g < w.geoms.size(); ++g)
    if (w.geoms[g].body == body) {
      if (found >= 0) return -1;
      found = static_cast<int>(g);
    }
  return found;
}

std::vector<int> jointsOf(const World& w, int body) {
  std::vector<int> found;
  for (size_t j = 0; j < w.joints.size(); ++j)
    if (w.joints[j].body1 == body || w.joints[j].body2 == body) found.push_back(static_cast<int>(j));
  return found;
}

Vec3 gravityOn(const World& w, const Body& b) {
  return b.gravity && !b.kinematic ? w.settings.gravity : Vec3{0, 0, 0};
}

// Pendulum: the swing's axis (a hinge's own; a ball joint's, the normal of
// the plane holding the pivot-to-body line and gravity).
Vec3 swingAxis(const World& w, const Joint& j, const Body& b) {
  if (j.kind == JointKind::Hinge) return scaled(j.axis, 1.0 / length(j.axis));
  const Vec3 n = cross(minus(b.position, j.anchor), w.settings.gravity);
  const double size = length(n);
  return size > 0 ? scaled(n, 1.0 / size) : Vec3{0, 0, 0};
}

GhostRefusal refusedBounce(const World& w, int body) {
  const Body& b = w.bodies[static_cast<size_t>(body)];
  const Vec3 g = gravityOn(w, b);
  if (!(length(g) > 0)) return {"law", "\"bounce\" needs the body under gravity (it has none)"};
  const int geom = onlyGeomOf(w, body);
  if (geom < 0 || w.geoms[static_cast<size_t>(geom)].shape != ShapeKind::Sphere)
    return {"law", "\"bounce\" needs a body whose one geom is a sphere (body " + std::to_string(body) + "'s is not)"};
  std::string why;
  const int plane = groundPlane(w, why);
  if (plane < 0) return {"law", "\"bounce\": " + why};
  const auto& p = w.geoms[static_cast<size_t>(plane)].plane;
  const Vec3 n{p[0], p[1], p[2]};
  if (length(cross(g, n)) > PARALLEL * length(g) || dot(g, n) >= 0)
    return {"law", "\"bounce\" needs gravity along the plane's normal, towards the plane (geoms[" + std::to_string(plane) +
                       "] and settings.gravity are not)"};
  if (length(across(b.linearVelocity, n)) > PARALLEL * std::max(1.0, length(b.linearVelocity)))
    return {"law", "\"bounce\" is vertical motion: bodies[" + std::to_string(body) +
                       "].linear_velocity must be along the plane's normal"};
  if (!w.mayTouch(geom, plane))
    return {"law", "\"bounce\": geoms[" + std::to_string(geom) + "] never touches the plane geoms[" +
                       std::to_string(plane) + "] (its category and collide bits)"};
  const Geom& sphere = w.geoms[static_cast<size_t>(geom)];
  const Vec3 centre = plus(b.position, rotated(b.orientation, sphere.position));
  if (dot(centre, n) - p[3] < sphere.size[0] * (1 - 1e-9))
    return {"law", "\"bounce\": body " + std::to_string(body) + " starts inside the plane"};
  return {};
}

GhostRefusal refusedPendulum(const World& w, int body) {
  const Body& b = w.bodies[static_cast<size_t>(body)];
  const std::vector<int> joints = jointsOf(w, body);
  if (joints.size() != 1)
    return {"law", "\"pendulum\" needs body " + std::to_string(body) + " held by one joint to the world (it has " +
                       std::to_string(joints.size()) + ")"};
  const Joint& j = w.joints[static_cast<size_t>(joints[0])];
  const std::string named = "joints[" + std::to_string(joints[0]) + "]";
  if (j.kind != JointKind::Hinge && j.kind != JointKind::Ball)
    return {"law", "\"pendulum\" needs a hinge or a ball joint (" + named + " is a " + jointName(j.kind) + ")"};
  if (j.body1 != -1 && j.body2 != -1) return {"law", "\"pendulum\" needs " + named + " to join the body to the world"};
  if (j.kind == JointKind::Hinge && (std::isfinite(j.lowStop) || std::isfinite(j.highStop)))
    return {"law", "\"pendulum\": " + named + " has stops, which the law has not"};
  const Vec3 g = gravityOn(w, b);
  const Vec3 a = swingAxis(w, j, b);
  if (!(length(a) > 0))
    return {"law", "\"pendulum\": body " + std::to_string(body) + " hangs straight on a ball joint: no plane of swing"};
  if (!(length(across(g, a)) > 0)) return {"law", "\"pendulum\" needs gravity across the swing's axis"};
  if (!(length(across(minus(b.position, j.anchor), a)) > 0))
    return {"law", "\"pendulum\": body " + std::to_string(body) + "'s centre of mass is on the swing's axis"};
  if (length(across(b.angularVelocity, a)) > PARALLEL * std::max(1.0, length(b.angularVelocity)))
    return {"law", "\"pendulum\" is a swing in one plane: bodies[" + std::to_string(body) +
                       "].angular_velocity must be along the swing's axis"};
  return {};
}

}  // namespace

GhostRefusal ghostRefusal(const World& w) {
  if (!w.ghost.on) return {};
  const int body = w.ghost.body;
  for (size_t i = 0; i < w.events.size(); ++i)
    if (w.events[i].body == body)
      return {"body", "body " + std::to_string(body) + " is " +
                          (w.events[i].kind == EventKind::Drop ? "dropped in" : "pushed") + " by events[" +
                          std::to_string(i) + "]; the law follows the file's start state alone"};
  if (w.ghost.law == GhostLaw::Pendulum) return refusedPendulum(w, body);
  const std::vector<int> joints = jointsOf(w, body);
  if (!joints.empty())
    return {"law", std::string("\"") + ghostLawName(w.ghost.law) + "\" is a free body's: body " + std::to_string(body) +
                       " has a joint (joints[" + std::to_string(joints[0]) + "])"};
  if (w.ghost.law == GhostLaw::Bounce) return refusedBounce(w, body);
  return {};
}

GhostMotion::GhostMotion(const World& w) : law_(w.ghost.law) {
  const Body& b = w.bodies[static_cast<size_t>(w.ghost.body)];
  start_ = b.position;
  orientation_ = b.orientation;
  velocity_ = b.linearVelocity;
  gravity_ = gravityOn(w, b);
  g_ = length(gravity_);
  for (const Geom& geom : w.geoms)
    if (geom.body == w.ghost.body) shapes_.push_back(geom);
  if (law_ == GhostLaw::Bounce) {
    std::string why;
    const Geom& plane = w.geoms[static_cast<size_t>(groundPlane(w, why))];
    const int geom = onlyGeomOf(w, w.ghost.body);
    const Geom& sphere = w.geoms[static_cast<size_t>(geom)];
    normal_ = {plane.plane[0], plane.plane[1], plane.plane[2]};
    const Vec3 centre = plus(b.position, rotated(b.orientation, sphere.position));
    // Contact when the sphere's centre is its radius above the plane.
    height_ = std::max(0.0, dot(centre, normal_) - plane.plane[3] - sphere.size[0]);
    rise_ = dot(velocity_, normal_);
    for (size_t g = 0; g < w.geoms.size(); ++g)
      if (&w.geoms[g] == &plane) {
        const Surface& s = w.surfaceBetween(geom, static_cast<int>(g));
        // Without restitution ODE's contact is perfectly inelastic: the ball stays down.
        restitution_ = s.bounce ? s.restitution : 0.0;
        bounceVelocity_ = s.bounce ? s.bounceVelocity : 0.0;
      }
  } else if (law_ == GhostLaw::Pendulum) {
    const Joint& j = w.joints[static_cast<size_t>(jointsOf(w, w.ghost.body)[0])];
    pivot_ = j.anchor;
    axis_ = swingAxis(w, j, b);
    const Vec3 arm = across(minus(b.position, pivot_), axis_);
    const Vec3 down = across(gravity_, axis_);
    const Vec3 hang = scaled(down, 1.0 / length(down));
    angle_ = std::atan2(dot(cross(hang, arm), axis_), dot(hang, arm));
    angleRate_ = dot(b.angularVelocity, axis_);
    // The small-angle law of a body swinging about a fixed axis: I theta'' = -m g d theta.
    const double d = length(arm);
    const double inertia = inertiaAbout(b, axis_) + b.mass * d * d;
    frequency_ = std::sqrt(b.mass * length(down) * d / inertia);
  }
}

double GhostMotion::bounceHeight(double time, std::vector<GhostImpact>* impacts) const {
  double h = height_, v = rise_, elapsed = 0.0, left = std::max(0.0, time);
  for (long flight = 0; flight < MOST_FLIGHTS; ++flight) {
    // The flight from height h at speed v (away from the ground) lands after T.
    const double impact = std::sqrt(v * v + 2 * g_ * h);
    const double landing = (v + impact) / g_;
    if (left < landing) return h + v * left - g_ * left * left / 2;
    left -= landing;
    elapsed += landing;
    if (impacts) impacts->push_back({elapsed, impact});
    // An impact slower than the surface's bounce_velocity does not bounce.
    const double up = impact < bounceVelocity_ ? 0.0 : restitution_ * impact;
    if (2 * up / g_ < SHORTEST_FLIGHT) return 0.0;  // at rest on the ground
    h = 0.0;
    v = up;
    // e = 1: every flight is the same; skip the whole ones before `time`.
    if (up == impact && !impacts) left = std::fmod(left, 2 * up / g_);
  }
  return 0.0;
}

GhostPose GhostMotion::at(double time) const {
  const double t = std::max(0.0, time);
  switch (law_) {
    case GhostLaw::Ballistic:
      return {plus(plus(start_, scaled(velocity_, t)), scaled(gravity_, t * t / 2)), orientation_};
    case GhostLaw::Bounce:
      return {plus(start_, scaled(normal_, bounceHeight(t, nullptr) - height_)), orientation_};
    case GhostLaw::Pendulum: {
      const double angle = angle_ * std::cos(frequency_ * t) + angleRate_ / frequency_ * std::sin(frequency_ * t);
      const Quat by = turn(axis_, angle - angle_);
      return {plus(pivot_, rotated(by, minus(start_, pivot_))), product(by, orientation_)};
    }
  }
  return {start_, orientation_};
}

std::vector<GhostImpact> GhostMotion::impacts(double until) const {
  std::vector<GhostImpact> found;
  if (law_ != GhostLaw::Bounce) return found;
  bounceHeight(until, &found);
  return found;
}

std::string GhostMotion::legend() const {
  switch (law_) {
    case GhostLaw::Ballistic: return "ghost: analytic ballistic arc (no contact)";
    case GhostLaw::Bounce: return "ghost: analytic bounce off the ground, e = " + number(restitution_);
    case GhostLaw::Pendulum:
      return "ghost: analytic small-angle swing, period " + number(2 * PI / frequency_) + " s";
  }
  return "ghost";
}

}  // namespace odelab::world
