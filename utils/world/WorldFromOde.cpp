#include "WorldFromOde.h"

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

namespace odelab::world {

namespace {

Vec3 vec(const dReal* v) { return {v[0], v[1], v[2]}; }
Quat quat(const dReal* q) { return {q[0], q[1], q[2], q[3]}; }

Geom geomOf(dGeomID geom, int body) {
  Geom g;
  g.body = body;
  switch (dGeomGetClass(geom)) {
    case dBoxClass: {
      dVector3 sides;
      dGeomBoxGetLengths(geom, sides);
      g.shape = ShapeKind::Box;
      g.size = vec(sides);
      break;
    }
    case dSphereClass:
      g.shape = ShapeKind::Sphere;
      g.size = {dGeomSphereGetRadius(geom), 0, 0};
      break;
    case dCapsuleClass: {
      dReal radius, length;
      dGeomCapsuleGetParams(geom, &radius, &length);
      g.shape = ShapeKind::Capsule;
      g.size = {radius, length, 0};
      break;
    }
    case dCylinderClass: {
      dReal radius, length;
      dGeomCylinderGetParams(geom, &radius, &length);
      g.shape = ShapeKind::Cylinder;
      g.size = {radius, length, 0};
      break;
    }
    case dPlaneClass: {
      dVector4 p;
      dGeomPlaneGetParams(geom, p);
      g.shape = ShapeKind::Plane;
      g.plane = {p[0], p[1], p[2], p[3]};
      break;
    }
    default:
      throw std::runtime_error("a geom of ODE class " + std::to_string(dGeomGetClass(geom)) +
                               " has no place in the world format (box, sphere, plane, capsule, cylinder)");
  }
  if (g.shape != ShapeKind::Plane) {
    if (body >= 0) {
      g.position = vec(dGeomGetOffsetPosition(geom));
      dQuaternion q;
      dGeomGetOffsetQuaternion(geom, q);
      g.orientation = quat(q);
    } else {
      g.position = vec(dGeomGetPosition(geom));
      dQuaternion q;
      dGeomGetQuaternion(geom, q);
      g.orientation = quat(q);
    }
  }
  g.category = static_cast<std::uint32_t>(dGeomGetCategoryBits(geom));
  g.collide = static_cast<std::uint32_t>(dGeomGetCollideBits(geom));
  return g;
}

Joint jointOf(dJointID joint, const OdeIndex& index) {
  Joint j;
  auto bodyAt = [&](int i) {
    const dBodyID body = dJointGetBody(joint, i);
    return body ? index.bodyIndex.at(body) : -1;
  };
  j.body1 = bodyAt(0);
  j.body2 = bodyAt(1);
  dVector3 v;
  switch (dJointGetType(joint)) {
    // A joint to the static world keeps its world anchor as given
    // (Anchor2): the very numbers to set it with again.
    case dJointTypeBall:
      j.kind = JointKind::Ball;
      if (j.body2 < 0)
        dJointGetBallAnchor2(joint, v);
      else
        dJointGetBallAnchor(joint, v);
      j.anchor = vec(v);
      j.erp = dJointGetBallParam(joint, dParamERP);
      j.cfm = dJointGetBallParam(joint, dParamCFM);
      break;
    case dJointTypeHinge:
      j.kind = JointKind::Hinge;
      if (j.body2 < 0)
        dJointGetHingeAnchor2(joint, v);
      else
        dJointGetHingeAnchor(joint, v);
      j.anchor = vec(v);
      dJointGetHingeAxis(joint, v);
      j.axis = vec(v);
      // No erp or cfm: a hinge's rows take the world's (its dParamCFM is a motor's).
      j.lowStop = dJointGetHingeParam(joint, dParamLoStop);
      j.highStop = dJointGetHingeParam(joint, dParamHiStop);
      break;
    case dJointTypeSlider:
      j.kind = JointKind::Slider;
      dJointGetSliderAxis(joint, v);
      j.axis = vec(v);
      j.lowStop = dJointGetSliderParam(joint, dParamLoStop);
      j.highStop = dJointGetSliderParam(joint, dParamHiStop);
      break;
    case dJointTypeFixed:
      j.kind = JointKind::Fixed;
      j.erp = dJointGetFixedParam(joint, dParamERP);
      j.cfm = dJointGetFixedParam(joint, dParamCFM);
      break;
    default:
      throw std::runtime_error("an ODE joint of type " + std::to_string(dJointGetType(joint)) +
                               " has no place in the world format (ball, hinge, slider, fixed)");
  }
  return j;
}

int surfaceIndex(World& world, const Surface& surface) {
  for (size_t i = 0; i < world.surfaces.size(); ++i)
    if (world.surfaces[i] == surface) return static_cast<int>(i);
  world.surfaces.push_back(surface);
  return static_cast<int>(world.surfaces.size()) - 1;
}

// Every pair of geoms that may touch, with one index at or above `from`. On
// the first description the commonest surface becomes the default, so a
// file lists only the pairs that differ from it.
void describePairs(const SurfaceOf& surfaceOf, World& world, const OdeIndex& index, int from) {
  std::vector<PairSurface> found;
  const int count = static_cast<int>(world.geoms.size());
  for (int b = std::max(from, 1); b < count; ++b)
    for (int a = 0; a < b; ++a) {
      // A geom gone with its body (index null) touches nothing any more.
      if (!index.geoms[a] || !index.geoms[b] || !world.mayTouch(a, b)) continue;
      dSurfaceParameters parameters{};
      surfaceOf(index.geoms[a], index.geoms[b], parameters);
      found.push_back({a, b, surfaceIndex(world, odelab::world::surfaceOf(parameters))});
    }
  if (world.surfaces.empty()) world.surfaces.push_back(Surface{});
  if (from == 0) {
    std::vector<int> uses(world.surfaces.size(), 0);
    for (const PairSurface& pair : found) ++uses[pair.surface];
    world.defaultSurface = static_cast<int>(std::max_element(uses.begin(), uses.end()) - uses.begin());
  }
  for (const PairSurface& pair : found)
    if (pair.surface != world.defaultSurface) world.pairSurfaces.push_back(pair);
}

}  // namespace

Settings settingsOf(dWorldID world, const WorldSettings& settings, int maxContacts, const char* spaceName) {
  Settings s;
  s.step = settings.step;
  dVector3 g;
  dWorldGetGravity(world, g);
  s.gravity = vec(g);
  s.erp = settings.erp;
  s.cfm = settings.cfm;
  s.quickStep = settings.solver == Solver::QuickStep;
  s.iterations = settings.iterations;
  s.sorW = settings.sor;
  s.contactMaxCorrectingVelocity = dWorldGetContactMaxCorrectingVel(world);
  s.contactSurfaceLayer = dWorldGetContactSurfaceLayer(world);
  s.maxContacts = maxContacts;
  s.space = spaceName;
  return s;
}

Surface surfaceOf(const dSurfaceParameters& p) {
  Surface s;
  s.mu = p.mu;
  s.bounce = (p.mode & dContactBounce) != 0;
  if (s.bounce) {
    s.restitution = p.bounce;
    s.bounceVelocity = p.bounce_vel;
  }
  s.softErp = (p.mode & dContactSoftERP) != 0;
  if (s.softErp) s.softErpValue = p.soft_erp;
  s.softCfm = (p.mode & dContactSoftCFM) != 0;
  if (s.softCfm) s.softCfmValue = p.soft_cfm;
  s.approx1 = (p.mode & dContactApprox1) == dContactApprox1;
  const int known = dContactBounce | dContactSoftERP | dContactSoftCFM | dContactApprox1;
  if (p.mode & ~known)
    throw std::runtime_error("a contact surface uses ODE mode bits " + std::to_string(p.mode & ~known) +
                             " that the world format does not describe (it has friction, bounce, soft ERP and CFM, the pyramid)");
  return s;
}

dSurfaceParameters odeSurface(const Surface& s) {
  dSurfaceParameters p{};
  p.mu = s.mu;
  if (s.bounce) {
    p.mode |= dContactBounce;
    p.bounce = s.restitution;
    p.bounce_vel = s.bounceVelocity;
  }
  if (s.softErp) {
    p.mode |= dContactSoftERP;
    p.soft_erp = s.softErpValue;
  }
  if (s.softCfm) {
    p.mode |= dContactSoftCFM;
    p.soft_cfm = s.softCfmValue;
  }
  if (s.approx1) p.mode |= dContactApprox1;
  return p;
}

Body bodyOf(dBodyID body) {
  Body b;
  dMass m;
  dBodyGetMass(body, &m);
  b.mass = m.mass;
  b.inertia = {m.I[0], m.I[5], m.I[10], m.I[1], m.I[2], m.I[6]};
  b.position = vec(dBodyGetPosition(body));
  b.orientation = quat(dBodyGetQuaternion(body));
  b.linearVelocity = vec(dBodyGetLinearVel(body));
  b.angularVelocity = vec(dBodyGetAngularVel(body));
  b.enabled = dBodyIsEnabled(body) != 0;
  b.kinematic = dBodyIsKinematic(body) != 0;
  b.gravity = dBodyGetGravityMode(body) != 0;
  b.maxAngularSpeed = dBodyGetMaxAngularSpeed(body);
  b.autoDisable.on = dBodyGetAutoDisableFlag(body) != 0;
  b.autoDisable.linearThreshold = dBodyGetAutoDisableLinearThreshold(body);
  b.autoDisable.angularThreshold = dBodyGetAutoDisableAngularThreshold(body);
  b.autoDisable.steps = dBodyGetAutoDisableSteps(body);
  b.autoDisable.time = dBodyGetAutoDisableTime(body);
  b.autoDisable.averageSamples = static_cast<int>(dBodyGetAutoDisableAverageSamplesCount(body));
  return b;
}

void describeNewObjects(const std::vector<std::unique_ptr<AbstractObject>>& objects, const SurfaceOf& surfaceOf,
                        World& world, OdeIndex& index) {
  const int firstGeom = static_cast<int>(world.geoms.size());
  const int firstBody = static_cast<int>(world.bodies.size());
  for (const auto& object : objects) {
    const dGeomID geom = object->getGeom();
    if (index.geomIndex.count(geom)) continue;
    const dBodyID body = object->getBody();
    int b = -1;
    if (body) {
      auto found = index.bodyIndex.find(body);
      if (found == index.bodyIndex.end()) {
        b = static_cast<int>(world.bodies.size());
        index.bodyIndex[body] = b;
        index.bodies.push_back(body);
        world.bodies.push_back(bodyOf(body));
      } else {
        b = found->second;
      }
    }
    index.geomIndex[geom] = static_cast<int>(world.geoms.size());
    index.geoms.push_back(geom);
    world.geoms.push_back(geomOf(geom, b));
  }
  // The new bodies' joints, each once, oldest first: ODE lists a body's
  // joints newest first, and the order decides the solver's row order.
  std::set<dJointID> known(index.joints.begin(), index.joints.end());
  for (size_t b = static_cast<size_t>(firstBody); b < index.bodies.size(); ++b) {
    const dBodyID body = index.bodies[b];
    for (int i = dBodyGetNumJoints(body) - 1; i >= 0; --i) {
      const dJointID joint = dBodyGetJoint(body, i);
      if (dJointGetType(joint) == dJointTypeContact || known.count(joint)) continue;
      const dBodyID other = dJointGetBody(joint, 0) == body ? dJointGetBody(joint, 1) : dJointGetBody(joint, 0);
      if (other && !index.bodyIndex.count(other)) continue;  // met again with the other body
      known.insert(joint);
      index.joints.push_back(joint);
      Joint described = jointOf(joint, index);
      // ODE copies the world's ERP and CFM into a ball or fixed joint when it
      // is made: a joint still at them takes the world's, and is written so,
      // not as a value of its own that an engine would have to translate.
      if (described.erp == world.settings.erp) described.erp = std::numeric_limits<double>::quiet_NaN();
      if (described.cfm == world.settings.cfm) described.cfm = std::numeric_limits<double>::quiet_NaN();
      world.joints.push_back(described);
    }
  }
  describePairs(surfaceOf, world, index, firstGeom);
}

void describeSurfaces(const SurfaceOf& surfaceOf, World& world, const OdeIndex& index) {
  world.surfaces.clear();
  world.pairSurfaces.clear();
  world.defaultSurface = 0;
  describePairs(surfaceOf, world, index, 0);
}

}  // namespace odelab::world
