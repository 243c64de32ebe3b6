#include "BulletContacts.h"

#include <algorithm>
#include <cmath>

namespace odelab::engines::bullet {

namespace {

std::uint64_t pairKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

// Bullet calls this for every contact point it adds or refreshes, after it
// combined the two objects' materials: the pair's own surface replaces them.
// The wrappers name the leaf shapes, so a compound's child is its own geom.
bool contactAdded(btManifoldPoint& point, const btCollisionObjectWrapper* a, int, int,
                  const btCollisionObjectWrapper* b, int, int) {
  const auto* rules = static_cast<const ContactRules*>(a->getCollisionObject()->getUserPointer());
  if (!rules) rules = static_cast<const ContactRules*>(b->getCollisionObject()->getUserPointer());
  const int geomA = a->getCollisionShape()->getUserIndex();
  const int geomB = b->getCollisionShape()->getUserIndex();
  if (!rules || geomA < 0 || geomB < 0) return false;
  const ContactSurface& s = rules->between(geomA, geomB);
  point.m_combinedFriction = s.friction;
  point.m_combinedRestitution = s.restitution;
  // ODE's soft ERP and CFM per contact: Bullet scales a contact's CFM by
  // 1/step as ODE does, so the values carry over unchanged.
  point.m_contactPointFlags &= ~(BT_CONTACT_FLAG_HAS_CONTACT_ERP | BT_CONTACT_FLAG_HAS_CONTACT_CFM);
  if (s.hasErp) {
    point.m_contactERP = s.erp;
    point.m_contactPointFlags |= BT_CONTACT_FLAG_HAS_CONTACT_ERP;
  }
  if (s.hasCfm) {
    point.m_contactCFM = s.cfm;
    point.m_contactPointFlags |= BT_CONTACT_FLAG_HAS_CONTACT_CFM;
  }
  return true;
}

ContactSurface translate(const world::Surface& surface, Notes& notes) {
  ContactSurface out;
  if (std::isinf(surface.mu)) {
    out.friction = INFINITE_FRICTION;
    notes.add("infinite friction (mu = infinity) became Bullet friction coefficient " + number(INFINITE_FRICTION) +
              " (Bullet's friction is always finite)");
  } else {
    out.friction = surface.mu;
    if (!surface.approx1 && surface.mu > 0)
      notes.add("friction mu = " + number(surface.mu) +
                " without dContactApprox1 is a force limit of mu newtons in ODE; Bullet's friction is always "
                "Coulomb's (mu times the normal force), so it became coefficient " + number(surface.mu));
  }
  out.restitution = surface.bounce ? surface.restitution : 0.0;
  out.hasErp = surface.softErp;
  out.erp = surface.softErpValue;
  out.hasCfm = surface.softCfm;
  out.cfm = surface.softCfmValue;
  return out;
}

}  // namespace

ContactRules::ContactRules() { gContactAddedCallback = &contactAdded; }

void ContactRules::update(const world::World& world, Notes& notes) {
  world_ = &world;
  defaultSurface_ = world.defaultSurface;
  pairs_.clear();
  std::vector<bool> used(world.surfaces.size(), false);
  used.at(static_cast<size_t>(world.defaultSurface)) = true;
  for (const world::PairSurface& pair : world.pairSurfaces) {
    pairs_[pairKey(pair.geom1, pair.geom2)] = pair.surface;
    used.at(static_cast<size_t>(pair.surface)) = true;
  }
  surfaces_.clear();
  bounces_ = false;
  std::vector<double> thresholds;
  for (size_t i = 0; i < world.surfaces.size(); ++i) {
    const world::Surface& s = world.surfaces[i];
    surfaces_.push_back(used[i] ? translate(s, notes) : ContactSurface{});
    if (used[i] && s.bounce && s.restitution > 0) {
      bounces_ = true;
      thresholds.push_back(s.bounceVelocity);
    }
  }
  if (bounces_) {
    // Bullet has one restitution threshold for the whole world.
    const auto [low, high] = std::minmax_element(thresholds.begin(), thresholds.end());
    restitutionThreshold_ = *low;
    if (*high != *low)
      notes.add("ODE's bounce velocity differs between surfaces (" + number(*low) + " to " + number(*high) +
                " m/s); Bullet has one restitution threshold for the world, set to the lowest, " + number(*low) +
                " m/s");
  }
}

const ContactSurface& ContactRules::between(int geom1, int geom2) const {
  const auto found = pairs_.find(pairKey(geom1, geom2));
  return surfaces_[found == pairs_.end() ? defaultSurface_ : found->second];
}

void ContactRules::attach(btCollisionObject& object, const std::vector<int>& geoms, bool fixed, Notes& notes) {
  int id;
  if (freeObjects_.empty()) {
    id = static_cast<int>(objects_.size());
    objects_.emplace_back();
  } else {
    id = freeObjects_.back();
    freeObjects_.pop_back();
  }
  objects_[id] = {geoms, fixed};
  object.setUserIndex(id);
  object.setUserPointer(this);
  object.setCollisionFlags(object.getCollisionFlags() | btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
  // The filter works on whole objects: a compound whose geoms have different
  // collide bits touches what any of them may touch.
  for (int g : geoms) {
    const world::Geom& a = world_->geoms[g];
    const world::Geom& b = world_->geoms[geoms[0]];
    if (a.category != b.category || a.collide != b.collide) {
      notes.add("geoms on one body with different collide bits: Bullet filters whole bodies, so each of them "
                "touches what any of them may touch");
      break;
    }
  }
}

void ContactRules::detach(btCollisionObject& object) {
  const int id = object.getUserIndex();
  if (id >= 0 && id < static_cast<int>(objects_.size())) {
    objects_[id] = {};
    freeObjects_.push_back(id);
  }
  object.setUserIndex(-1);
  object.setUserPointer(nullptr);
}

bool ContactRules::geomsMayTouch(int a, int b) const {
  const world::Geom& ga = world_->geoms[a];
  const world::Geom& gb = world_->geoms[b];
  return (ga.category & gb.collide) || (gb.category & ga.collide);
}

bool ContactRules::needBroadphaseCollision(btBroadphaseProxy* proxy0, btBroadphaseProxy* proxy1) const {
  const auto* a = static_cast<const btCollisionObject*>(proxy0->m_clientObject);
  const auto* b = static_cast<const btCollisionObject*>(proxy1->m_clientObject);
  if (!a || !b || a->getUserPointer() != this || b->getUserPointer() != this) return false;
  const ObjectGeoms& oa = objects_[a->getUserIndex()];
  const ObjectGeoms& ob = objects_[b->getUserIndex()];
  if (oa.fixed && ob.fixed) return false;  // static and kinematic geoms never push each other
  for (int ga : oa.geoms)
    for (int gb : ob.geoms)
      if (geomsMayTouch(ga, gb)) return true;
  return false;
}

}  // namespace odelab::engines::bullet
