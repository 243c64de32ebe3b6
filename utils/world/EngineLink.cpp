#include "EngineLink.h"

#include <chrono>
#include <cmath>
#include <set>
#include <string>

namespace odelab::world {

namespace {

bool same(const BodyState& a, const BodyState& b) {
  return a.position == b.position && a.orientation == b.orientation && a.linearVelocity == b.linearVelocity &&
         a.angularVelocity == b.angularVelocity && a.enabled == b.enabled;
}

bool nonZero(const dReal* v) { return v[0] != 0 || v[1] != 0 || v[2] != 0; }

// Adds the wall time of the scope it lives in to a total.
class WallClock {
 public:
  explicit WallClock(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~WallClock() { total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  WallClock(const WallClock&) = delete;
  WallClock& operator=(const WallClock&) = delete;

 private:
  double& total_;
  std::chrono::steady_clock::time_point start_;
};

bool finite(const BodyState& s) {
  for (const auto* v : {&s.position, &s.linearVelocity, &s.angularVelocity})
    for (double x : *v)
      if (!std::isfinite(x)) return false;
  for (double x : s.orientation)
    if (!std::isfinite(x)) return false;
  return true;
}

}  // namespace

BodyState EngineLink::odeState(dBodyID body) const {
  BodyState s;
  const dReal* p = dBodyGetPosition(body);
  const dReal* q = dBodyGetQuaternion(body);
  const dReal* v = dBodyGetLinearVel(body);
  const dReal* w = dBodyGetAngularVel(body);
  s.position = {p[0], p[1], p[2]};
  s.orientation = {q[0], q[1], q[2], q[3]};
  s.linearVelocity = {v[0], v[1], v[2]};
  s.angularVelocity = {w[0], w[1], w[2]};
  s.enabled = dBodyIsEnabled(body) != 0;
  return s;
}

void EngineLink::start(std::unique_ptr<Engine> engine, const std::string& name, EngineSetting setting, Settings settings,
                       const std::vector<std::unique_ptr<AbstractObject>>& objects, const SurfaceOf& surfaceOf,
                       const FileOrigin* file) {
  engine_ = std::move(engine);
  linkWallSeconds_ = 0.0;  // the engine's clocks start again with it (Engine::reset)
  file_ = file ? *file : FileOrigin{};
  name_ = name;
  setting_ = setting;
  world_ = World{};
  index_ = OdeIndex{};
  world_.settings = std::move(settings);
  describeNewObjects(objects, surfaceOf, world_, index_);
  adoptFile(0);
  engine_->build(world_);
  written_.clear();
  for (const dBodyID body : index_.bodies) written_.push_back(odeState(body));
  bodyChanges_ = AbstractObject::bodyChanges();
}

bool EngineLink::restart(Settings settings, const std::vector<std::unique_ptr<AbstractObject>>& objects,
                         const SurfaceOf& surfaceOf, const FileOrigin* file) {
  if (!engine_ || !engine_->reset()) return false;
  start(std::move(engine_), name_, setting_, std::move(settings), objects, surfaceOf, file);
  return true;
}

void EngineLink::sendEdits(const std::vector<std::unique_ptr<AbstractObject>>& objects, const SurfaceOf& surfaceOf) {
  const WallClock clock(linkWallSeconds_);
  // A body the scene made kinematic or dynamic again (test10 parks a cube
  // that passed the wall) is another body to an engine: removed, and added
  // anew under a new index.
  for (size_t i = 0; i < index_.bodies.size(); ++i) {
    const dBodyID body = index_.bodies[i];
    if (!body || (dBodyIsKinematic(body) != 0) == world_.bodies[i].kinematic) continue;
    forget(static_cast<int>(i));
    bodyChanges_ = 0;  // so that the objects are looked at again below
  }
  if (AbstractObject::bodyChanges() != bodyChanges_) {
    bodyChanges_ = AbstractObject::bodyChanges();
    // Removed first: a new body may take a removed one's address.
    std::set<dBodyID> liveBodies;
    std::set<dGeomID> liveGeoms;
    for (const auto& object : objects) {
      liveGeoms.insert(object->getGeom());
      if (const dBodyID body = object->getBody()) liveBodies.insert(body);
    }
    for (size_t i = 0; i < index_.bodies.size(); ++i)
      if (index_.bodies[i] && !liveBodies.count(index_.bodies[i])) forget(static_cast<int>(i));
    for (size_t i = 0; i < index_.geoms.size(); ++i)
      if (index_.geoms[i] && !liveGeoms.count(index_.geoms[i])) {
        index_.geomIndex.erase(index_.geoms[i]);
        index_.geoms[i] = nullptr;
      }
    const int firstBody = static_cast<int>(world_.bodies.size());
    const int firstGeom = static_cast<int>(world_.geoms.size());
    const int firstJoint = static_cast<int>(world_.joints.size());
    describeNewObjects(objects, surfaceOf, world_, index_);
    adoptFile(static_cast<size_t>(firstJoint));
    if (static_cast<int>(world_.geoms.size()) > firstGeom) {
      engine_->add(world_, firstBody, firstGeom, firstJoint);
      for (size_t i = static_cast<size_t>(firstBody); i < index_.bodies.size(); ++i)
        written_.push_back(odeState(index_.bodies[i]));
    }
  }
  for (size_t i = 0; i < index_.bodies.size(); ++i) {
    const dBodyID body = index_.bodies[i];
    if (!body) continue;
    const BodyState now = odeState(body);
    if (!same(now, written_[i])) {
      engine_->setState(static_cast<int>(i), now);
      written_[i] = now;
    }
    const dReal* force = dBodyGetForce(body);
    const dReal* torque = dBodyGetTorque(body);
    if (nonZero(force) || nonZero(torque)) {
      engine_->applyForce(static_cast<int>(i), {force[0], force[1], force[2]}, {torque[0], torque[1], torque[2]});
      // ODE clears a body's forces when it steps; here it does not step.
      dBodySetForce(body, 0, 0, 0);
      dBodySetTorque(body, 0, 0, 0);
    }
  }
}

void EngineLink::changeSettings(const Settings& settings, const SurfaceOf& surfaceOf) {
  const WallClock clock(linkWallSeconds_);
  world_.settings = settings;
  describeSurfaces(surfaceOf, world_, index_);
  adoptFileSurfaces();
  engine_->changeSettings(world_);
}

void EngineLink::adoptFile(size_t firstJoint) {
  if (!file_.world) return;
  for (size_t k = firstJoint; k < world_.joints.size(); ++k) {
    const int own = file_.jointOf(index_.joints[k]);
    if (own < 0) continue;
    world_.joints[k].erp = file_.world->joints[static_cast<size_t>(own)].erp;
    world_.joints[k].cfm = file_.world->joints[static_cast<size_t>(own)].cfm;
  }
  adoptFileSurfaces();
}

// The file's surface list, its default and its pairs, as long as every pair
// that may touch still meets the file's surface: once the scene changed one
// (the mu knob overrides every contact), what ODE's callback gives is the world.
void EngineLink::adoptFileSurfaces() {
  if (!file_.world) return;
  const World& file = *file_.world;
  std::vector<PairSurface> pairs;
  const int count = static_cast<int>(world_.geoms.size());
  for (int b = 1; b < count; ++b)
    for (int a = 0; a < b; ++a) {
      if (!index_.geoms[static_cast<size_t>(a)] || !index_.geoms[static_cast<size_t>(b)] || !world_.mayTouch(a, b)) continue;
      const int fa = file_.geomOf(index_.geoms[static_cast<size_t>(a)]);
      const int fb = file_.geomOf(index_.geoms[static_cast<size_t>(b)]);
      if (fa < 0 || fb < 0 || world_.surfaceBetween(a, b) != file.surfaceBetween(fa, fb)) return;
      for (const PairSurface& own : file.pairSurfaces)
        if ((own.geom1 == fa && own.geom2 == fb) || (own.geom1 == fb && own.geom2 == fa)) pairs.push_back({a, b, own.surface});
    }
  world_.surfaces = file.surfaces;
  world_.defaultSurface = file.defaultSurface;
  world_.pairSurfaces = std::move(pairs);
}

void EngineLink::forget(int i) {
  const dBodyID body = index_.bodies[static_cast<size_t>(i)];
  engine_->remove(i);
  world_.bodies[static_cast<size_t>(i)].removed = true;
  index_.bodyIndex.erase(body);
  index_.bodies[static_cast<size_t>(i)] = nullptr;
  // Its geoms too: should the body live on (made kinematic), they are described again with it.
  for (size_t g = 0; g < index_.geoms.size(); ++g)
    if (index_.geoms[g] && world_.geoms[g].body == i) {
      index_.geomIndex.erase(index_.geoms[g]);
      index_.geoms[g] = nullptr;
    }
}

double EngineLink::step() {
  const WallClock clock(linkWallSeconds_);
  const double before = engine_->engineWallSeconds();
  engine_->step();
  // Every state looked at before any is written: ODE would take a
  // non-finite quaternion for an error of its own.
  std::vector<BodyState> states(index_.bodies.size());
  for (size_t i = 0; i < index_.bodies.size(); ++i) {
    if (!index_.bodies[i]) continue;
    states[i] = engine_->state(static_cast<int>(i));
    if (!finite(states[i])) throw EngineError("body " + std::to_string(i) + " has a state that is not finite");
  }
  for (size_t i = 0; i < index_.bodies.size(); ++i)
    if (index_.bodies[i]) writeBack(static_cast<int>(i), states[i]);
  return engine_->engineWallSeconds() - before;
}

void EngineLink::writeBack(int i, const BodyState& s) {
  const dBodyID body = index_.bodies[static_cast<size_t>(i)];
  dBodySetPosition(body, s.position[0], s.position[1], s.position[2]);
  const dQuaternion q = {s.orientation[0], s.orientation[1], s.orientation[2], s.orientation[3]};
  dBodySetQuaternion(body, q);
  dBodySetLinearVel(body, s.linearVelocity[0], s.linearVelocity[1], s.linearVelocity[2]);
  dBodySetAngularVel(body, s.angularVelocity[0], s.angularVelocity[1], s.angularVelocity[2]);
  if (s.enabled && !dBodyIsEnabled(body)) dBodyEnable(body);
  if (!s.enabled && dBodyIsEnabled(body)) dBodyDisable(body);
  // As ODE holds it (it normalises the quaternion): the next comparison is exact.
  written_[static_cast<size_t>(i)] = odeState(body);
}

}  // namespace odelab::world
