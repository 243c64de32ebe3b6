#pragma once

// Which Bullet objects may touch and with what surface, pair by pair, as the
// world description says (World::mayTouch, World::surfaceBetween). Bullet
// would multiply two materials and filter with an AND of group and mask
// bits; ODE's scenes give each geom pair its own surface and let two geoms
// touch when either's category meets the other's collide bits. So every
// object carries CF_CUSTOM_MATERIAL_CALLBACK and a pointer to these rules,
// the contact-added callback writes the pair's surface into each new
// contact point, and a broadphase filter applies ODE's collide bits.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "BulletCommon.h"

namespace odelab::engines::bullet {

// One world surface as Bullet's contact point holds it.
struct ContactSurface {
  double friction = 0;
  double restitution = 0;
  bool hasErp = false, hasCfm = false;
  double erp = 0, cfm = 0;
};

// ODE's infinite friction in Bullet: a coefficient no contact here reaches.
constexpr double INFINITE_FRICTION = 1e6;

class ContactRules : public btOverlapFilterCallback {
 public:
  ContactRules();
  // Re-reads surfaces, pair surfaces and collide bits from `world`, which
  // must outlive these rules (the engine's own copy).
  void update(const world::World& world, Notes& notes);
  const ContactSurface& between(int geom1, int geom2) const;
  // Whether a surface in use bounces, and the one impact speed below which
  // Bullet applies no restitution (ODE's bounce_velocity).
  bool bounces() const { return bounces_; }
  double restitutionThreshold() const { return restitutionThreshold_; }

  // Ties a collision object to these rules: its geoms (by index) and whether
  // it never moves by contact (static or kinematic).
  void attach(btCollisionObject& object, const std::vector<int>& geoms, bool fixed, Notes& notes);
  void detach(btCollisionObject& object);

  bool needBroadphaseCollision(btBroadphaseProxy* proxy0, btBroadphaseProxy* proxy1) const override;

 private:
  struct ObjectGeoms {
    std::vector<int> geoms;
    bool fixed = false;
  };
  bool geomsMayTouch(int a, int b) const;

  const world::World* world_ = nullptr;
  std::vector<ContactSurface> surfaces_;  // by world surface index
  int defaultSurface_ = 0;
  std::unordered_map<std::uint64_t, int> pairs_;  // (geom1 << 32 | geom2) -> surface
  bool bounces_ = false;
  double restitutionThreshold_ = 0;
  std::vector<ObjectGeoms> objects_;  // by the object's user index
  std::vector<int> freeObjects_;
};

}  // namespace odelab::engines::bullet
