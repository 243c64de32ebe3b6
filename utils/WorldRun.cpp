#include "WorldRun.h"

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "FormatValue.h"
#include "StateHash.h"

namespace odelab {

namespace {

// The bounds of a blow-up that stays finite: BodyStateWatch.h.
constexpr double RUNAWAY_SPEED = BodyStateWatch::RUNAWAY_SPEED;  // m/s
constexpr double RUNAWAY_SPIN = BodyStateWatch::RUNAWAY_SPIN;    // rad/s

// Distinct bodies: the geoms of a composite body share one.
std::set<dBodyID> bodiesOf(const std::vector<std::unique_ptr<AbstractObject>>& objects) {
  std::set<dBodyID> bodies;
  for (const auto& object : objects)
    if (const dBodyID body = object->getBody()) bodies.insert(body);
  return bodies;
}

}  // namespace

void WorldRun::create(unsigned seed) {
  random_.seed(seed);
  dRandSetSeed(seed);
  world_ = dWorldCreate();
  // The world steps with an implementation of its own rather than ODE's
  // default, which all worlds share, so that one an ODE error has left in
  // a bad state can be dropped with its world (AbstractWindow::advanceFrame).
  // A scene may replace it in configureWorld() (test5 --threads).
  if (!stepThreading_) stepThreading_ = dThreadingAllocateSelfThreadedImplementation();
  dWorldSetStepThreadingImplementation(world_, dThreadingImplementationGetFunctions(stepThreading_), stepThreading_);
  contactGroup_ = dJointGroupCreate(0);
  space_ = nullptr;
  simulatedTime_ = 0.0;
  steps_ = 0;
  contactsLastStep_ = 0;
  wallSeconds_ = 0.0;
  engineWallSeconds_ = 0.0;
  blowUpReason_.clear();
  engineFailed_ = false;
}

void WorldRun::setSpaceKind(SpaceKind kind, const SceneBounds& bounds) {
  dSpaceID next = nullptr;
  switch (kind) {
    case SpaceKind::Simple: next = dSimpleSpaceCreate(nullptr); break;
    case SpaceKind::Hash: next = dHashSpaceCreate(nullptr); break;
    case SpaceKind::SweepAndPrune: next = dSweepAndPruneSpaceCreate(nullptr, dSAP_AXES_XZY); break;
    case SpaceKind::QuadTree: {
      // Centred on the scene, covering its bounds; y is up so the tree splits x and z.
      const dVector3 centre{bounds.centre[0], bounds.centre[1], bounds.centre[2], 0};
      const dVector3 extents{4 * bounds.radius, 4 * bounds.radius, 4 * bounds.radius, 0};
      next = dQuadTreeSpaceCreate(nullptr, centre, extents, 6);
      break;
    }
  }
  // Space cleanup is off: geoms belong to their objects, not to the space.
  dSpaceSetCleanup(next, 0);
  if (space_) {
    // Every geom in the space is an object's (a scene adds geoms only
    // through objects). They are found through the objects, not the space:
    // ODE's quadtree space cannot list its geoms (dSpaceGetGeom fails with
    // "not yet implemented"), which input fuzzing found.
    for (const auto& object : objects_) {
      const dGeomID geom = object->getGeom();
      if (!geom || dGeomGetSpace(geom) != space_) continue;
      dSpaceRemove(space_, geom);
      dSpaceAdd(next, geom);
    }
    if (dSpaceGetNumGeoms(space_) != 0) throw std::logic_error("setSpaceKind: the space holds a geom of no object");
    dSpaceDestroy(space_);
  }
  space_ = next;
  spaceKind_ = kind;
}

void WorldRun::destroy() {
  objects_.clear();
  if (contactGroup_) dJointGroupDestroy(contactGroup_);
  if (space_) dSpaceDestroy(space_);
  if (world_) dWorldDestroy(world_);
  contactGroup_ = nullptr;
  space_ = nullptr;
  world_ = nullptr;
}

void WorldRun::freeThreading() {
  if (stepThreading_) dThreadingFreeImplementation(stepThreading_);
  stepThreading_ = nullptr;
}

void WorldRun::carryWorldErpCfmToJoints(double oldErp, double oldCfm, double erp, double cfm) const {
  std::set<dJointID> joints;
  for (const dBodyID body : bodiesOf(objects_))
    for (int i = 0; i < dBodyGetNumJoints(body); ++i) joints.insert(dBodyGetJoint(body, i));
  for (const dJointID joint : joints) {
    if (dJointGetType(joint) == dJointTypeBall) {
      if (dJointGetBallParam(joint, dParamERP) == oldErp) dJointSetBallParam(joint, dParamERP, erp);
      if (dJointGetBallParam(joint, dParamCFM) == oldCfm) dJointSetBallParam(joint, dParamCFM, cfm);
    } else if (dJointGetType(joint) == dJointTypeFixed) {
      if (dJointGetFixedParam(joint, dParamERP) == oldErp) dJointSetFixedParam(joint, dParamERP, erp);
      if (dJointGetFixedParam(joint, dParamCFM) == oldCfm) dJointSetFixedParam(joint, dParamCFM, cfm);
    }
  }
}

std::string WorldRun::stateProblem() const {
  auto length = [](const dReal* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); };
  for (const auto& object : objects_) {
    const dBodyID body = object->getBody();
    if (!body) continue;
    const dReal* position = dBodyGetPosition(body);
    const dReal* velocity = dBodyGetLinearVel(body);
    const dReal* spin = dBodyGetAngularVel(body);
    for (const dReal* v : {position, velocity, spin})
      if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) return "non-finite body state";
    // Finite but absurd: energy has run away (no scene comes near these).
    if (length(velocity) > RUNAWAY_SPEED)
      return "runaway energy: a body moves at " + formatValue(length(velocity)) + " m/s";
    if (length(spin) > RUNAWAY_SPIN)
      return "runaway energy: a body spins at " + formatValue(length(spin)) + " rad/s";
  }
  return {};
}

std::uint64_t WorldRun::stateHash() const {
  // Each object's body, in creation order.
  std::vector<dBodyID> bodies;
  for (const auto& object : objects_)
    if (const dBodyID body = object->getBody()) bodies.push_back(body);
  return odelab::stateHash(world_, steps_, simulatedTime_, bodies);
}

int WorldRun::bodyCount() const { return static_cast<int>(bodiesOf(objects_).size()); }

int WorldRun::disabledBodyCount() const {
  int count = 0;
  for (const dBodyID body : bodiesOf(objects_))
    if (!dBodyIsEnabled(body)) ++count;
  return count;
}

PickHit WorldRun::pickAt(const double origin[3], const double direction[3]) const {
  return pickObject(objects_, origin, direction);
}

}  // namespace odelab
