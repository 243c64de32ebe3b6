#include "WorldRun.h"

#include <cmath>
#include <limits>
#include <set>

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

void WorldRun::destroyWorld() {
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
