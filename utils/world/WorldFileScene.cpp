#include "WorldFileScene.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "Box.h"
#include "Plane.h"
#include "SpaceKind.h"
#include "Sphere.h"
#include "WorldFromOde.h"
#include "WorldJson.h"

namespace odelab::world {

namespace {

WorldSettings settingsFrom(const World& world) {
  const Settings& s = world.settings;
  if (s.gravity[0] != 0 || s.gravity[2] != 0 || s.gravity[1] > 0)
    throw WorldFileError("settings.gravity: this program runs gravity along -y only ([0, -g, 0]); the file has [" +
                         std::to_string(s.gravity[0]) + ", " + std::to_string(s.gravity[1]) + ", " +
                         std::to_string(s.gravity[2]) + "]");
  WorldSettings w;
  w.erp = s.erp;
  w.cfm = s.cfm;
  w.step = s.step;
  w.iterations = s.iterations;
  w.sor = s.sorW;
  w.solver = s.quickStep ? Solver::QuickStep : Solver::WorldStep;
  w.gravity = -s.gravity[1];
  return w;
}

bool identity(const Vec3& p, const Quat& q) {
  return p == Vec3{0, 0, 0} && q == Quat{1, 0, 0, 0};
}

}  // namespace

WorldFileScene::WorldFileScene(World world) : AbstractWindow(settingsFrom(world)), world_(std::move(world)) {
  for (size_t i = 0; i < world_.geoms.size(); ++i)
    if (world_.geoms[i].shape == ShapeKind::Capsule || world_.geoms[i].shape == ShapeKind::Cylinder)
      throw WorldFileError("geoms[" + std::to_string(i) + "].shape: ODE Lab's window draws boxes, spheres and planes; a " +
                           shapeName(world_.geoms[i].shape) + " it cannot run here");
  fileMu_ = world_.surfaces[world_.defaultSurface].mu;
  useContactChoices(fileMu_);
  for (Knob& knob : tuning().knobs())
    if (knob.name == "max_contacts") knob.set(world_.settings.maxContacts);
}

void WorldFileScene::configureWorld() {
  SpaceKind kind = SpaceKind::Simple;
  parseSpaceKind(world_.settings.space, kind);
  setSpaceKind(kind);
  dWorldSetContactMaxCorrectingVel(world(), world_.settings.contactMaxCorrectingVelocity);
  dWorldSetContactSurfaceLayer(world(), world_.settings.contactSurfaceLayer);
  // Bodies take the world's auto-disable values when made: the first body's,
  // so that a file of one kind of body sets nothing body by body.
  if (!world_.bodies.empty()) {
    const AutoDisable& a = world_.bodies.front().autoDisable;
    dWorldSetAutoDisableFlag(world(), a.on);
    dWorldSetAutoDisableLinearThreshold(world(), a.linearThreshold);
    dWorldSetAutoDisableAngularThreshold(world(), a.angularThreshold);
    dWorldSetAutoDisableSteps(world(), a.steps);
    dWorldSetAutoDisableTime(world(), a.time);
    dWorldSetAutoDisableAverageSamplesCount(world(), static_cast<unsigned>(a.averageSamples));
  }
}

void WorldFileScene::buildScene() {
  geomIndex_.clear();
  bodyOwner_.assign(world_.bodies.size(), nullptr);
  // One object per geom, in the file's order (the order the program made
  // them: the collision order, and the state hash's body order). A second
  // geom of a body joins the first one's body as attach() does in a scene.
  std::vector<AbstractObject*> objects;
  for (size_t i = 0; i < world_.geoms.size(); ++i) {
    const Geom& g = world_.geoms[i];
    AbstractObject* object = nullptr;
    switch (g.shape) {
      case ShapeKind::Box: object = &add<Box>(world(), space(), g.size[0], g.size[1], g.size[2], 1.0); break;
      case ShapeKind::Sphere: object = &add<Sphere>(world(), space(), g.size[0], 1.0); break;
      case ShapeKind::Plane: object = &add<Plane>(space(), g.plane[0], g.plane[1], g.plane[2], g.plane[3]); break;
      default: break;  // refused in the constructor
    }
    geomIndex_[object->getGeom()] = static_cast<int>(i);
    objects.push_back(object);
    if (g.shape == ShapeKind::Plane) continue;
    if (g.body < 0) {
      object->setAsFixedGeom();
      dGeomSetPosition(object->getGeom(), g.position[0], g.position[1], g.position[2]);
      const dQuaternion q = {g.orientation[0], g.orientation[1], g.orientation[2], g.orientation[3]};
      dGeomSetQuaternion(object->getGeom(), q);
    } else if (!bodyOwner_[static_cast<size_t>(g.body)]) {
      bodyOwner_[static_cast<size_t>(g.body)] = object;
    } else {
      object->attach(*bodyOwner_[static_cast<size_t>(g.body)]);
    }
  }
  for (size_t b = 0; b < world_.bodies.size(); ++b) buildBody(static_cast<int>(b), *bodyOwner_[b]);
  // Offsets last: attach() moved each composite body and re-seated its geoms.
  for (size_t i = 0; i < world_.geoms.size(); ++i) {
    const Geom& g = world_.geoms[i];
    if (g.body < 0 || g.shape == ShapeKind::Plane) continue;
    const bool shared = std::count_if(world_.geoms.begin(), world_.geoms.end(), [&](const Geom& o) { return o.body == g.body; }) > 1;
    if (!shared && identity(g.position, g.orientation)) continue;
    dGeomSetOffsetPosition(objects[i]->getGeom(), g.position[0], g.position[1], g.position[2]);
    const dQuaternion q = {g.orientation[0], g.orientation[1], g.orientation[2], g.orientation[3]};
    dGeomSetOffsetQuaternion(objects[i]->getGeom(), q);
  }
  for (const Joint& joint : world_.joints) buildJoint(joint);
  for (size_t i = 0; i < world_.geoms.size(); ++i) {
    dGeomSetCategoryBits(objects[i]->getGeom(), world_.geoms[i].category);
    dGeomSetCollideBits(objects[i]->getGeom(), world_.geoms[i].collide);
  }
}

void WorldFileScene::buildBody(int index, AbstractObject& owner) {
  const Body& b = world_.bodies[static_cast<size_t>(index)];
  const dBodyID body = owner.getBody();
  dMass m;
  dMassSetZero(&m);
  m.mass = b.mass;
  m.I[0] = b.inertia[0];
  m.I[5] = b.inertia[1];
  m.I[10] = b.inertia[2];
  m.I[1] = m.I[4] = b.inertia[3];
  m.I[2] = m.I[8] = b.inertia[4];
  m.I[6] = m.I[9] = b.inertia[5];
  dBodySetMass(body, &m);
  dBodySetPosition(body, b.position[0], b.position[1], b.position[2]);
  const dQuaternion q = {b.orientation[0], b.orientation[1], b.orientation[2], b.orientation[3]};
  dBodySetQuaternion(body, q);
  dBodySetLinearVel(body, b.linearVelocity[0], b.linearVelocity[1], b.linearVelocity[2]);
  dBodySetAngularVel(body, b.angularVelocity[0], b.angularVelocity[1], b.angularVelocity[2]);
  dBodySetGravityMode(body, b.gravity ? 1 : 0);
  if (std::isfinite(b.maxAngularSpeed)) dBodySetMaxAngularSpeed(body, b.maxAngularSpeed);
  const AutoDisable& a = b.autoDisable;
  if ((dBodyGetAutoDisableFlag(body) != 0) != a.on) dBodySetAutoDisableFlag(body, a.on);
  if (dBodyGetAutoDisableLinearThreshold(body) != a.linearThreshold) dBodySetAutoDisableLinearThreshold(body, a.linearThreshold);
  if (dBodyGetAutoDisableAngularThreshold(body) != a.angularThreshold)
    dBodySetAutoDisableAngularThreshold(body, a.angularThreshold);
  if (dBodyGetAutoDisableSteps(body) != a.steps) dBodySetAutoDisableSteps(body, a.steps);
  if (dBodyGetAutoDisableTime(body) != a.time) dBodySetAutoDisableTime(body, a.time);
  if (static_cast<int>(dBodyGetAutoDisableAverageSamplesCount(body)) != a.averageSamples)
    dBodySetAutoDisableAverageSamplesCount(body, static_cast<unsigned>(a.averageSamples));
  if (b.kinematic) dBodySetKinematic(body);
  if (!b.enabled) dBodyDisable(body);
}

void WorldFileScene::buildJoint(const Joint& j) {
  auto bodyOf = [&](int b) { return b < 0 ? dBodyID{} : bodyOwner_[static_cast<size_t>(b)]->getBody(); };
  dJointID joint = nullptr;
  switch (j.kind) {
    case JointKind::Ball:
      joint = dJointCreateBall(world(), 0);
      dJointAttach(joint, bodyOf(j.body1), bodyOf(j.body2));
      dJointSetBallAnchor(joint, j.anchor[0], j.anchor[1], j.anchor[2]);
      if (!std::isnan(j.erp)) dJointSetBallParam(joint, dParamERP, j.erp);
      if (!std::isnan(j.cfm)) dJointSetBallParam(joint, dParamCFM, j.cfm);
      break;
    case JointKind::Hinge:
      joint = dJointCreateHinge(world(), 0);
      dJointAttach(joint, bodyOf(j.body1), bodyOf(j.body2));
      dJointSetHingeAnchor(joint, j.anchor[0], j.anchor[1], j.anchor[2]);
      dJointSetHingeAxis(joint, j.axis[0], j.axis[1], j.axis[2]);
      if (std::isfinite(j.lowStop)) dJointSetHingeParam(joint, dParamLoStop, j.lowStop);
      if (std::isfinite(j.highStop)) dJointSetHingeParam(joint, dParamHiStop, j.highStop);
      if (!std::isnan(j.cfm)) dJointSetHingeParam(joint, dParamCFM, j.cfm);
      break;
    case JointKind::Slider:
      joint = dJointCreateSlider(world(), 0);
      dJointAttach(joint, bodyOf(j.body1), bodyOf(j.body2));
      dJointSetSliderAxis(joint, j.axis[0], j.axis[1], j.axis[2]);
      if (std::isfinite(j.lowStop)) dJointSetSliderParam(joint, dParamLoStop, j.lowStop);
      if (std::isfinite(j.highStop)) dJointSetSliderParam(joint, dParamHiStop, j.highStop);
      if (!std::isnan(j.cfm)) dJointSetSliderParam(joint, dParamCFM, j.cfm);
      break;
    case JointKind::Fixed:
      joint = dJointCreateFixed(world(), 0);
      dJointAttach(joint, bodyOf(j.body1), bodyOf(j.body2));
      dJointSetFixed(joint);
      break;
  }
}

void WorldFileScene::setContactSurface(dGeomID o1, dGeomID o2, dSurfaceParameters& surface) {
  const auto a = geomIndex_.find(o1);
  const auto b = geomIndex_.find(o2);
  surface = odeSurface(a == geomIndex_.end() || b == geomIndex_.end() ? world_.surfaces[world_.defaultSurface]
                                                                       : world_.surfaceBetween(a->second, b->second));
  // F / G, --mu or the panel: once moved from the file's value, every contact takes it.
  if (contactMu() != fileMu_) surface.mu = contactMu();
}

SceneBounds WorldFileScene::bounds() const {
  if (world_.bodies.empty()) return AbstractWindow::bounds();
  double low[3] = {1e300, 1e300, 1e300}, high[3] = {-1e300, -1e300, -1e300};
  for (const Body& b : world_.bodies)
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], b.position[k]);
      high[k] = std::max(high[k], b.position[k]);
    }
  SceneBounds bounds{{(low[0] + high[0]) / 2, (low[1] + high[1]) / 2, (low[2] + high[2]) / 2}, 0};
  for (int k = 0; k < 3; ++k) bounds.radius = std::max(bounds.radius, (high[k] - low[k]) / 2);
  bounds.radius = std::max(bounds.radius + 5.0, 8.0);
  return bounds;
}

std::string WorldFileScene::fileTitle(const std::string& path) const {
  const std::string name = path.substr(path.find_last_of("/\\") + 1);
  if (!world_.title.empty()) return world_.title + " (" + name + ")";
  return name;
}

void WorldFileScene::addHudLines(std::vector<std::string>& lines) const {
  auto count = [](size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); };
  lines.push_back("world file" + (world_.scene.empty() ? std::string() : " from " + world_.scene) + ": " +
                  count(world_.bodies.size(), "body", "bodies") + ", " + count(world_.geoms.size(), "geom", "geoms") +
                  ", " + count(world_.joints.size(), "joint", "joints"));
}

}  // namespace odelab::world
