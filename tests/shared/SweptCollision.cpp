#include "SweptCollision.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace odelab {

namespace {

constexpr double INF = std::numeric_limits<double>::infinity();

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double length(const double* a) { return std::sqrt(dot(a, a)); }
bool isZero(const double* a) { return a[0] == 0.0 && a[1] == 0.0 && a[2] == 0.0; }

// 3x3 matrices, row-major; column i of a geom's rotation is its axis i.
struct Matrix {
  double m[9];
  double column(int row, int i) const { return m[3 * row + i]; }
};

Matrix fromOde(const dReal* r) {  // ODE's 3x4 row-major
  return {{r[0], r[1], r[2], r[4], r[5], r[6], r[8], r[9], r[10]}};
}

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c.m[3 * i + j] += a.m[3 * i + k] * b.m[3 * k + j];
  return c;
}

void apply(const Matrix& a, const double* v, double* out) {
  for (int i = 0; i < 3; ++i) out[i] = a.m[3 * i] * v[0] + a.m[3 * i + 1] * v[1] + a.m[3 * i + 2] * v[2];
}

// The rotation through the rotation vector v (Rodrigues).
Matrix rotationBy(const double* v) {
  const double angle = length(v);
  if (angle < 1e-300) return {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  const double k[3] = {v[0] / angle, v[1] / angle, v[2] / angle};
  const double s = std::sin(angle), c = 1.0 - std::cos(angle);
  return {{1 - c * (k[1] * k[1] + k[2] * k[2]), -s * k[2] + c * k[0] * k[1], s * k[1] + c * k[0] * k[2],
           s * k[2] + c * k[0] * k[1], 1 - c * (k[0] * k[0] + k[2] * k[2]), -s * k[0] + c * k[1] * k[2],
           -s * k[1] + c * k[0] * k[2], s * k[0] + c * k[1] * k[2], 1 - c * (k[0] * k[0] + k[1] * k[1])}};
}

// A geom's shape at some pose, in the terms the distance bounds need.
struct ShapeAt {
  enum Kind { Box, Sphere, Plane } kind;
  double centre[3];
  Matrix rotation;
  double half[3];  // box half-sides
  double radius;   // sphere
  double normal[3], offset;  // plane: normal . x = offset, solid below
  bool exact = true;         // false: another shape, held by this bounding box

  // Half-width along the unit direction n (the support): exact for boxes and spheres.
  double halfWidthAlong(const double* n) const {
    if (kind == Sphere) return radius;
    double width = 0.0;
    for (int i = 0; i < 3; ++i)
      width += half[i] * std::fabs(rotation.column(0, i) * n[0] + rotation.column(1, i) * n[1] +
                                   rotation.column(2, i) * n[2]);
    return width;
  }
  double boundingRadius() const { return kind == Sphere ? radius : length(half); }
  // Distance from the point x to this box (0 inside), and the closest point.
  double boxDistance(const double* x, double* closest) const {
    double excess[3], out[3];
    const double squared = excessOutside(x, excess);
    apply(rotation, excess, out);
    for (int k = 0; k < 3; ++k) closest[k] = x[k] - out[k];
    return std::sqrt(squared);
  }
  // How far the point x lies beyond this box's faces along each of its
  // axes (0 between a pair of faces), in the box's frame; the squared
  // distance from x to the box.
  double excessOutside(const double* x, double excess[3]) const {
    const double r[3] = {x[0] - centre[0], x[1] - centre[1], x[2] - centre[2]};
    double squared = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double local = rotation.column(0, i) * r[0] + rotation.column(1, i) * r[1] + rotation.column(2, i) * r[2];
      excess[i] = local - std::clamp(local, -half[i], half[i]);
      squared += excess[i] * excess[i];
    }
    return squared;
  }
};

ShapeAt describe(dGeomID geom) {
  ShapeAt shape{};
  const int kind = dGeomGetClass(geom);
  if (kind == dPlaneClass) {
    dVector4 plane;
    dGeomPlaneGetParams(geom, plane);
    shape.kind = ShapeAt::Plane;
    for (int k = 0; k < 3; ++k) shape.normal[k] = plane[k];
    shape.offset = plane[3];
    return shape;
  }
  if (kind == dBoxClass || kind == dSphereClass) {
    const dReal* c = dGeomGetPosition(geom);
    for (int k = 0; k < 3; ++k) shape.centre[k] = c[k];
    shape.rotation = fromOde(dGeomGetRotation(geom));
    if (kind == dSphereClass) {
      shape.kind = ShapeAt::Sphere;
      shape.radius = dGeomSphereGetRadius(geom);
    } else {
      shape.kind = ShapeAt::Box;
      dVector3 sides;
      dGeomBoxGetLengths(geom, sides);
      for (int k = 0; k < 3; ++k) shape.half[k] = 0.5 * sides[k];
    }
    return shape;
  }
  // Any other shape: its axis-aligned bounding box, which holds it.
  dReal aabb[6];
  dGeomGetAABB(geom, aabb);
  shape.kind = ShapeAt::Box;
  shape.exact = false;
  shape.rotation = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  for (int k = 0; k < 3; ++k) {
    shape.centre[k] = 0.5 * (aabb[2 * k] + aabb[2 * k + 1]);
    shape.half[k] = 0.5 * (aabb[2 * k + 1] - aabb[2 * k]);
  }
  return shape;
}

// Two boxes: the largest gap between their projections on the 15 separating
// axes (the 3 + 3 face normals and the 9 edge-edge cross products). It is
// at most the distance (a projection never lengthens), and positive exactly
// when they are apart (the separating axis theorem). Worked in a's frame:
// R is b's rotation seen from a (R[i][j] = a_i . b_j), t the centres'
// offset there, so each axis costs a few products (it runs in every probe
// of a time of impact).
double boxBoxSeparation(const ShapeAt& a, const ShapeAt& b, double enough) {
  const double between[3] = {b.centre[0] - a.centre[0], b.centre[1] - a.centre[1], b.centre[2] - a.centre[2]};
  double R[3][3], absR[3][3], t[3];
  for (int i = 0; i < 3; ++i) {
    t[i] = a.rotation.column(0, i) * between[0] + a.rotation.column(1, i) * between[1] +
           a.rotation.column(2, i) * between[2];
    for (int j = 0; j < 3; ++j) {
      R[i][j] = a.rotation.column(0, i) * b.rotation.column(0, j) + a.rotation.column(1, i) * b.rotation.column(1, j) +
                a.rotation.column(2, i) * b.rotation.column(2, j);
      absR[i][j] = std::fabs(R[i][j]);
    }
  }
  const double* ha = a.half;
  const double* hb = b.half;
  double best = -INF;
  for (int i = 0; i < 3; ++i)  // a's faces
    best = std::max(best, std::fabs(t[i]) - ha[i] - (hb[0] * absR[i][0] + hb[1] * absR[i][1] + hb[2] * absR[i][2]));
  for (int j = 0; j < 3; ++j)  // b's faces
    best = std::max(best, std::fabs(t[0] * R[0][j] + t[1] * R[1][j] + t[2] * R[2][j]) -
                              (ha[0] * absR[0][j] + ha[1] * absR[1][j] + ha[2] * absR[2][j]) - hb[j]);
  // Any axis gives a lower bound: far apart, the face normals are enough
  // and the edge axes are left out (most of a far sweep's cost).
  if (best > enough) return best;
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      // a_i x b_j, of length sin(angle) = sqrt(1 - R[i][j]^2).
      const double n = std::sqrt(std::max(0.0, 1.0 - R[i][j] * R[i][j]));
      if (n < 1e-9) continue;  // parallel edges: the face axes cover them
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double centres = std::fabs(t[i2] * R[i1][j] - t[i1] * R[i2][j]);
      const double widthA = ha[i1] * absR[i2][j] + ha[i2] * absR[i1][j];
      const double widthB = hb[j1] * absR[i][j2] + hb[j2] * absR[i][j1];
      best = std::max(best, (centres - widthA - widthB) / n);
    }
  }
  return best;
}

// A lower bound on the distance between a moving box or sphere and a fixed
// box, sphere or plane; zero or less exactly when they overlap. Where it is
// above `enough`, it may be less tight than it could be.
double separation(const ShapeAt& moving, const ShapeAt& fixed, double enough = 0.0) {
  if (fixed.kind == ShapeAt::Plane)
    return dot(fixed.normal, moving.centre) - fixed.offset - moving.halfWidthAlong(fixed.normal);
  if (moving.kind == ShapeAt::Sphere && fixed.kind == ShapeAt::Sphere) {
    const double r[3] = {moving.centre[0] - fixed.centre[0], moving.centre[1] - fixed.centre[1],
                         moving.centre[2] - fixed.centre[2]};
    return length(r) - moving.radius - fixed.radius;
  }
  double closest[3];
  if (fixed.kind == ShapeAt::Sphere) return moving.boxDistance(fixed.centre, closest) - fixed.radius;
  if (moving.kind == ShapeAt::Sphere) return fixed.boxDistance(moving.centre, closest) - moving.radius;
  return boxBoxSeparation(moving, fixed, enough);
}

// The moving geom's shape at fraction s of the motion, from its shape at the
// start and its offset from the body's origin (the centre of rotation).
ShapeAt shapeAtFraction(const ShapeAt& start, const double origin[3], const StepMotion& motion, double s) {
  const double turn[3] = {s * motion.turn[0], s * motion.turn[1], s * motion.turn[2]};
  if (isZero(turn)) {  // it only travels (the common case)
    ShapeAt shape = start;
    for (int k = 0; k < 3; ++k) shape.centre[k] += s * motion.travel[k];
    return shape;
  }
  const Matrix r = rotationBy(turn);
  const double offset[3] = {start.centre[0] - origin[0], start.centre[1] - origin[1], start.centre[2] - origin[2]};
  ShapeAt shape = start;
  apply(r, offset, shape.centre);
  for (int k = 0; k < 3; ++k) shape.centre[k] += origin[k] + s * motion.travel[k];
  shape.rotation = multiply(r, start.rotation);
  return shape;
}

// The body's pose at the start of a motion, to move it along it and back.
struct BodyPose {
  dBodyID body;
  double position[3];
  Matrix rotation;
  dQuaternion quaternion;
  // Whether it has been moved: setting a pose renormalises the rotation and
  // marks the geoms for a new bounding box, which an unmoved body is spared.
  mutable bool moved = false;

  explicit BodyPose(dBodyID b) : body(b) {
    const dReal* p = dBodyGetPosition(b);
    for (int k = 0; k < 3; ++k) position[k] = p[k];
    rotation = fromOde(dBodyGetRotation(b));
    const dReal* q = dBodyGetQuaternion(b);
    for (int k = 0; k < 4; ++k) quaternion[k] = q[k];
  }
  void moveTo(const StepMotion& motion, double s) const {
    moved = true;
    dBodySetPosition(body, position[0] + s * motion.travel[0], position[1] + s * motion.travel[1],
                     position[2] + s * motion.travel[2]);
    const double turn[3] = {s * motion.turn[0], s * motion.turn[1], s * motion.turn[2]};
    if (isZero(turn)) return;  // a body that does not turn keeps its rotation
    const Matrix r = multiply(rotationBy(turn), rotation);
    dMatrix3 ode = {r.m[0], r.m[1], r.m[2], 0, r.m[3], r.m[4], r.m[5], 0, r.m[6], r.m[7], r.m[8], 0};
    dBodySetRotation(body, ode);
  }
  void restore() const {
    if (!moved) return;
    moved = false;
    dBodySetPosition(body, position[0], position[1], position[2]);
    dBodySetQuaternion(body, quaternion);
  }
};

bool collides(dGeomID a, dGeomID b) {
  dContactGeom contact;
  return dCollide(a, b, 1, &contact, sizeof(dContactGeom)) > 0;
}

// How far any point of the body may move per unit fraction of the motion:
// |travel| plus |turn| times the reach of the geom from the body's origin.
double speedBound(const ShapeAt& moving, const double origin[3], const StepMotion& motion) {
  const double offset[3] = {moving.centre[0] - origin[0], moving.centre[1] - origin[1],
                            moving.centre[2] - origin[2]};
  return length(motion.travel) + length(motion.turn) * (length(offset) + moving.boundingRadius());
}

// Conservative advancement; leaves the body at the pose of the last probe.
Impact advance(const BodyPose& pose, dGeomID moving, const ShapeAt& start, const StepMotion& motion,
               dGeomID fixedGeom, const ShapeAt& fixed, double depth, int maxIterations) {
  const double speed = speedBound(start, pose.position, motion);
  double s = 0.0;
  for (int i = 0; i < maxIterations; ++i) {
    const double gap = separation(shapeAtFraction(start, pose.position, motion, s), fixed, depth);
    // Boxes, spheres and planes overlap exactly where the bound is below
    // zero; for other shapes, held by their bounding boxes, ODE's own
    // dCollide says.
    const bool overlap = start.exact && fixed.exact
                             ? gap < 0.0
                             : gap <= 0.0 && (pose.moveTo(motion, s), collides(moving, fixedGeom));
    if (overlap) return {s == 0.0 ? Impact::AlreadyTouching : Impact::At, s};
    if (s >= 1.0 || speed <= 0.0) return {Impact::None, 0.0};
    // No point comes closer than gap in gap / speed; past the depth, step
    // so that the overlap stays within it.
    s = std::min(1.0, s + (gap > depth ? gap : std::max(gap, 0.0) + depth) / speed);
  }
  return {Impact::Unresolved, s};
}

}  // namespace

StepMotion nextStepMotion(dBodyID body, const double gravity[3], double step) {
  StepMotion motion;
  const dReal* v = dBodyGetLinearVel(body);
  const dReal* w = dBodyGetAngularVel(body);
  for (int k = 0; k < 3; ++k) {
    motion.travel[k] = (v[k] + gravity[k] * step) * step;
    motion.turn[k] = w[k] * step;
  }
  return motion;
}

double separationBound(dGeomID moving, dGeomID fixed) { return separation(describe(moving), describe(fixed)); }

Impact timeOfImpact(dBodyID body, dGeomID moving, const StepMotion& motion, dGeomID fixed, double depth,
                    int maxIterations) {
  const BodyPose pose(body);
  const Impact impact = advance(pose, moving, describe(moving), motion, fixed, describe(fixed), depth, maxIterations);
  pose.restore();
  return impact;
}

void SweptCollision::setStaticGeoms(const std::vector<dGeomID>& geoms) {
  statics_.clear();
  for (dGeomID geom : geoms) {
    StaticGeom shape{geom, dGeomGetClass(geom) == dPlaneClass, {}, {}, {}, 0.0};
    if (shape.plane) {
      dVector4 plane;
      dGeomPlaneGetParams(geom, plane);
      for (int k = 0; k < 3; ++k) shape.normal[k] = plane[k];
      shape.offset = plane[3];
    } else {
      dReal aabb[6];
      dGeomGetAABB(geom, aabb);
      for (int k = 0; k < 3; ++k) shape.lower[k] = aabb[2 * k], shape.upper[k] = aabb[2 * k + 1];
    }
    statics_.push_back(shape);
  }
}

namespace {

// Quick rejection: the geom's own bounding box (ODE's, at the start of the
// motion), swept along the travel and grown on every side by how far its
// turn can carry any point (|turn| x reach: an arc is no shorter than its
// chord), stays clear of the static geom's bounding box or plane. It holds
// the geom at every fraction of the motion, and for a box is far tighter
// than a sphere round it: most steps of a fast body end here.
bool sweptBoxMisses(const SweptCollision::StaticGeom& fixed, const double lower[3], const double upper[3],
                    const double d[3], double margin) {
  if (fixed.plane) {
    // The box's lowest corner along the normal, at the start and the end.
    double start = -fixed.offset;
    for (int k = 0; k < 3; ++k) start += fixed.normal[k] * (fixed.normal[k] > 0.0 ? lower[k] : upper[k]);
    return start > margin && start + dot(fixed.normal, d) > margin;
  }
  for (int k = 0; k < 3; ++k) {
    if (lower[k] + std::min(0.0, d[k]) - margin > fixed.upper[k]) return true;
    if (upper[k] + std::max(0.0, d[k]) + margin < fixed.lower[k]) return true;
  }
  return false;
}

double smallestHalfExtent(const ShapeAt& shape) {
  return shape.kind == ShapeAt::Sphere ? shape.radius : std::min({shape.half[0], shape.half[1], shape.half[2]});
}

}  // namespace

SweptCollision::Body SweptCollision::describeBody(dBodyID body, dGeomID geom) {
  const dReal* origin = dBodyGetPosition(body);
  const dReal* centre = dGeomGetPosition(geom);
  const double offset[3] = {centre[0] - origin[0], centre[1] - origin[1], centre[2] - origin[2]};
  double smallest, radius;
  if (dGeomGetClass(geom) == dSphereClass) {
    smallest = radius = dGeomSphereGetRadius(geom);
  } else {
    const ShapeAt shape = describe(geom);  // a box, or another shape's bounding box
    smallest = smallestHalfExtent(shape), radius = shape.boundingRadius();
  }
  return {body, geom, smallest, length(offset) + radius};
}

SweepResult SweptCollision::sweep(dBodyID body, dGeomID geom, double step, const double gravity[3], dWorldID world,
                                  dJointGroupID contacts) {
  return sweep(describeBody(body, geom), step, gravity, world, contacts);
}

SweepResult SweptCollision::sweep(const Body& moving, double step, const double gravity[3], dWorldID world,
                                  dJointGroupID contacts) {
  const dBodyID body = moving.body;
  const dGeomID geom = moving.geom;
  if (!dBodyIsEnabled(body)) return SweepResult::Slow;
  // The speed test and the quick rejection come first and touch only the
  // velocities and the bounding box: most steps of a fast body end there.
  const StepMotion motion = nextStepMotion(body, gravity, step);
  const double turnReach = length(motion.turn) * moving.reach;
  if (length(motion.travel) + turnReach <= options_.fastFraction * moving.smallestHalfExtent)
    return SweepResult::Slow;
  ++counts_.sweeps;
  // ODE computes this box for the coming collide anyway (the geom moved in
  // the last step): asking for it now costs nothing extra.
  dReal aabb[6];
  dGeomGetAABB(geom, aabb);
  const double lower[3] = {aabb[0], aabb[2], aabb[4]}, upper[3] = {aabb[1], aabb[3], aabb[5]};
  near_.clear();
  for (const StaticGeom& fixed : statics_)
    if (fixed.geom != geom && !sweptBoxMisses(fixed, lower, upper, motion.travel, turnReach)) near_.push_back(&fixed);
  if (near_.empty()) return SweepResult::Clear;
  const ShapeAt start = describe(geom);
  const BodyPose pose(body);
  Impact first{Impact::None, INF};
  bool unresolved = false;
  touching_.clear();
  for (const StaticGeom* fixed : near_) {
    const Impact impact = advance(pose, geom, start, motion, fixed->geom, describe(fixed->geom),
                                  options_.contactDepth, options_.maxIterations);
    if (impact.kind == Impact::AlreadyTouching) touching_.push_back(fixed);
    unresolved = unresolved || impact.kind == Impact::Unresolved;
    if (impact.kind == Impact::At && impact.fraction < first.fraction) first = impact;
  }
  // A body that already touches a geom keeps that contact wherever it is
  // moved, but is moved on only where that does not take it deeper into the
  // geom (a box sliding along the ground into a wall is; one driven into
  // the ground is not).
  bool clamp = first.kind == Impact::At;
  for (const StaticGeom* fixed : touching_) {
    const ShapeAt geomNow = describe(fixed->geom);
    const ShapeAt there = shapeAtFraction(start, pose.position, motion, first.fraction);
    clamp = clamp && separation(there, geomNow) >= separation(start, geomNow) - options_.contactDepth;
  }
  SweepResult result = SweepResult::Clear;
  const bool speculative = options_.speculativeContacts && start.kind == ShapeAt::Box;
  if (clamp) {
    pose.moveTo(motion, first.fraction);
    ++counts_.clamps;
    result = SweepResult::Clamped;
  } else {
    pose.restore();
    if (!touching_.empty()) result = SweepResult::Touching;
    if (unresolved && touching_.empty()) ++counts_.unresolved, result = SweepResult::Unresolved;
  }
  // Corners get contacts only where the body meets a static geom in this
  // step (or may: a search that ran out); a clear sweep has no corner that
  // reaches one.
  if (speculative && result != SweepResult::Clear) {
    double velocity[3];
    for (int k = 0; k < 3; ++k) velocity[k] = motion.travel[k] / step;
    for (const StaticGeom* fixed : near_)
      counts_.speculativeContacts +=
          addSpeculativeContacts(body, geom, fixed->geom, velocity, step, options_.speculativeClosing, world, contacts);
  }
  return result;
}

namespace {

// A corner of a box outside a static geom: where it is, how far from the
// geom, and the direction out of the geom toward it.
struct Corner {
  double position[3];
  double gap;  // <= 0: inside
  double normal[3];
};

// At most eight, on the stack: this runs in the step of every impact.
struct Corners {
  Corner corner[8];
  int count = 0;
  const Corner* begin() const { return corner; }
  const Corner* end() const { return corner + count; }
};

// The corners of `box` outside `wall` by at most `within` (m): the others
// are inside it already or cannot reach it this step, and cost only their
// gap (the closest point and the normal are worked out for the few kept).
Corners cornersWithin(const ShapeAt& box, const ShapeAt& wall, double within) {
  Corners corners;
  for (int index = 0; index < 8; ++index) {
    const double local[3] = {(index & 1 ? 1 : -1) * box.half[0], (index & 2 ? 1 : -1) * box.half[1],
                             (index & 4 ? 1 : -1) * box.half[2]};
    Corner c{};
    apply(box.rotation, local, c.position);
    for (int k = 0; k < 3; ++k) c.position[k] += box.centre[k];
    const double* x = c.position;
    if (wall.kind == ShapeAt::Plane) {
      c.gap = dot(wall.normal, x) - wall.offset;
      if (c.gap <= 0.0 || c.gap > within) continue;
      for (int k = 0; k < 3; ++k) c.normal[k] = wall.normal[k];
    } else if (wall.kind == ShapeAt::Sphere) {
      const double d[3] = {x[0] - wall.centre[0], x[1] - wall.centre[1], x[2] - wall.centre[2]};
      const double distance = length(d);
      c.gap = distance - wall.radius;
      if (c.gap <= 0.0 || c.gap > within) continue;
      for (int k = 0; k < 3; ++k) c.normal[k] = d[k] / distance;
    } else {
      double excess[3];
      const double squared = wall.excessOutside(x, excess);
      if (squared <= 0.0 || squared > within * within) continue;
      c.gap = std::sqrt(squared);
      for (double& e : excess) e /= c.gap;
      apply(wall.rotation, excess, c.normal);  // from the closest point out to the corner
    }
    corners.corner[corners.count++] = c;
  }
  return corners;
}

}  // namespace

int SweptCollision::addSpeculativeContacts(dBodyID body, dGeomID geom, dGeomID fixed, const double velocity[3],
                                           double step, double closing, dWorldID world, dJointGroupID contacts) {
  const ShapeAt box = describe(geom);
  const dReal* origin = dBodyGetPosition(body);
  const dReal* w = dBodyGetAngularVel(body);
  // How far a corner can move in the step: farther corners are not stopped this step.
  const double offset[3] = {box.centre[0] - origin[0], box.centre[1] - origin[1], box.centre[2] - origin[2]};
  const double spin = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  const double reach = (length(velocity) + spin * (length(offset) + box.boundingRadius())) * step;
  int added = 0;
  for (const Corner& c : cornersWithin(box, describe(fixed), reach)) {
    const double r[3] = {c.position[0] - origin[0], c.position[1] - origin[1], c.position[2] - origin[2]};
    const double u[3] = {velocity[0] + w[1] * r[2] - w[2] * r[1], velocity[1] + w[2] * r[0] - w[0] * r[2],
                         velocity[2] + w[0] * r[1] - w[1] * r[0]};
    if (dot(c.normal, u) >= 0.0) continue;  // moving away: nothing to stop
    dContact contact{};
    contact.surface.mode = dContactMotionN;
    contact.surface.mu = 0.0;                  // normal only: friction comes with the real contact
    contact.surface.motionN = -closing * c.gap / step;  // may close this much of the gap in the step
    for (int k = 0; k < 3; ++k) contact.geom.pos[k] = c.position[k], contact.geom.normal[k] = c.normal[k];
    contact.geom.depth = 0.0;
    contact.geom.g1 = geom;
    contact.geom.g2 = fixed;
    dJointAttach(dJointCreateContact(world, contacts, &contact), body, nullptr);
    ++added;
  }
  return added;
}

}  // namespace odelab


