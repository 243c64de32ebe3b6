#include "WorldRun.h"

#include <cmath>
#include <limits>
#include <set>

#include "FormatValue.h"

namespace odelab {

namespace {

// A blow-up that stays finite (runaway energy): no scene comes near these.
// 1e8 m/s is ten times the fastest launch any scene allows (test10's
// --velocity, at most 1e7 m/s); free fall at 1 g needs 118 days to reach it. There
// is no bound on distance: a body that falls off a platform (test4, test5)
// is 1e8 m down after 75 minutes, which a window session can last.
constexpr double RUNAWAY_SPEED = 1e8;  // m/s
constexpr double RUNAWAY_SPIN = 1e8;   // rad/s

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

bool WorldRun::stateSuspicious() const {
  // NaN fails every comparison, infinity the bounds: both land in stateProblem().
  constexpr double SPEED2 = RUNAWAY_SPEED * RUNAWAY_SPEED, SPIN2 = RUNAWAY_SPIN * RUNAWAY_SPIN;
  for (const auto& object : objects_) {
    const dBodyID body = object->getBody();
    if (!body) continue;
    const dReal* p = dBodyGetPosition(body);
    const dReal* v = dBodyGetLinearVel(body);
    const dReal* w = dBodyGetAngularVel(body);
    if (!(std::fabs(p[0]) + std::fabs(p[1]) + std::fabs(p[2]) <= std::numeric_limits<double>::max()) ||
        !(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] <= SPEED2) || !(w[0] * w[0] + w[1] * w[1] + w[2] * w[2] <= SPIN2))
      return true;
  }
  return false;
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
  // FNV-1a over the exact bytes of every body's position, orientation and
  // velocities, in creation order; cut to 52 bits so JSON's doubles hold it.
  std::uint64_t hash = 1469598103934665603ull;
  auto mix = [&hash](const dReal* values, int count) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(values);
    for (size_t i = 0; i < count * sizeof(dReal); ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  };
  for (const auto& object : objects_) {
    const dBodyID body = object->getBody();
    if (!body) continue;
    mix(dBodyGetPosition(body), 3);
    mix(dBodyGetQuaternion(body), 4);
    mix(dBodyGetLinearVel(body), 3);
    mix(dBodyGetAngularVel(body), 3);
  }
  return hash & ((1ull << 52) - 1);
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
