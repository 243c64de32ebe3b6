#include "WorldFileScene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/glm.hpp>

#include "Box.h"
#include "Camera.h"
#include "Cylindrical.h"
#include "Plane.h"
#include "SpaceKind.h"
#include "Sphere.h"
#include "WorldFromOde.h"
#include "WorldJson.h"

namespace odelab::world {

namespace {

// Gravity may point any way: its magnitude is the gravity knob's, its
// direction the file's (straight down, -y, when there is none).
WorldSettings settingsFrom(const World& world) {
  const Settings& s = world.settings;
  WorldSettings w;
  w.erp = s.erp;
  w.cfm = s.cfm;
  w.step = s.step;
  w.iterations = s.iterations;
  w.sor = s.sorW;
  w.solver = s.quickStep ? Solver::QuickStep : Solver::WorldStep;
  w.gravity = std::sqrt(s.gravity[0] * s.gravity[0] + s.gravity[1] * s.gravity[1] + s.gravity[2] * s.gravity[2]);
  if (w.gravity > 0)
    for (int k = 0; k < 3; ++k) w.down[k] = s.gravity[static_cast<size_t>(k)] / w.gravity;
  return w;
}

// Deeper than this at t = 0 is an overlap worth a warning, m: a body resting
// on another as exported touches within ODE's contact tolerance.
constexpr double OVERLAP_TOLERANCE = 1e-3;

bool identity(const Vec3& p, const Quat& q) {
  return p == Vec3{0, 0, 0} && q == Quat{1, 0, 0, 0};
}

}  // namespace

WorldFileScene::WorldFileScene(World world) : AbstractWindow(settingsFrom(world)), world_(std::move(world)) {
  origin_.world = &world_;
  origin_.geomOf = [this](dGeomID g) {
    const auto found = geomIndex_.find(g);
    return found == geomIndex_.end() ? -1 : found->second;
  };
  origin_.jointOf = [this](dJointID j) {
    const auto found = jointIndex_.find(j);
    return found == jointIndex_.end() ? -1 : found->second;
  };
  if (world_.ghost.on) ghost_ = std::make_unique<GhostMotion>(world_);
  fileMu_ = world_.surfaces[world_.defaultSurface].mu;
  useContactChoices(fileMu_);
  for (Knob& knob : tuning().knobs())
    if (knob.name == "max_contacts") knob.set(world_.settings.maxContacts);
}

WorldFileScene::~WorldFileScene() = default;

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
  jointIndex_.clear();
  bodyOwner_.assign(world_.bodies.size(), nullptr);
  nextEvent_ = 0;
  // A body dropped in later is not there at the start.
  std::vector<bool> now(world_.bodies.size(), true);
  for (const Event& e : world_.events)
    if (e.kind == EventKind::Drop && e.at > 0) now[static_cast<size_t>(e.body)] = false;
  buildGeoms(now, true);
  for (size_t j = 0; j < world_.joints.size(); ++j) jointIndex_[buildJoint(world_.joints[j])] = static_cast<int>(j);
  std::vector<dBodyID> bodies(world_.bodies.size(), nullptr);
  for (size_t b = 0; b < bodies.size(); ++b)
    if (bodyOwner_[b]) bodies[b] = bodyOwner_[b]->getBody();
  if (!warned_) warnOfOverlaps();
  warned_ = true;
  measures_ = std::make_unique<WorldMeasures>(world_, world(), space(), std::move(bodies));
}

// Each body its own colour, the same in every run (by its index in the
// file): three stacked boxes read as three. Hues a golden angle apart stay
// distinct for any count; none is the grey of static geoms.
Color WorldFileScene::bodyColor(int body) {
  const double hue = std::fmod(0.08 + 0.618033988749895 * body, 1.0) * 6.0;
  const double saturation = 0.55, value = 0.9;
  const int sector = static_cast<int>(hue);
  const double f = hue - sector;
  const float p = static_cast<float>(value * (1 - saturation)), q = static_cast<float>(value * (1 - saturation * f)),
              t = static_cast<float>(value * (1 - saturation * (1 - f))), v = static_cast<float>(value);
  switch (sector % 6) {
    case 0: return {v, t, p};
    case 1: return {q, v, p};
    case 2: return {p, v, t};
    case 3: return {p, q, v};
    case 4: return {t, p, v};
    default: return {v, p, q};
  }
}

void WorldFileScene::buildGeoms(const std::vector<bool>& bodies, bool statics) {
  // One object per geom, in the file's order (the order the program made
  // them: the collision order, and the state hash's body order). A second
  // geom of a body joins the first one's body as attach() does in a scene.
  std::vector<std::pair<size_t, AbstractObject*>> made;
  std::vector<int> geomsOfBody(world_.bodies.size(), 0);
  for (const Geom& g : world_.geoms)
    if (g.body >= 0) ++geomsOfBody[static_cast<size_t>(g.body)];
  for (size_t i = 0; i < world_.geoms.size(); ++i) {
    const Geom& g = world_.geoms[i];
    if (g.body < 0 ? !statics : !bodies[static_cast<size_t>(g.body)]) continue;
    AbstractObject* object = nullptr;
    switch (g.shape) {
      case ShapeKind::Box: object = &add<Box>(world(), space(), g.size[0], g.size[1], g.size[2], 1.0); break;
      case ShapeKind::Sphere: object = &add<Sphere>(world(), space(), g.size[0], 1.0); break;
      case ShapeKind::Capsule:
        object = &add<Cylindrical>(Shape::Capsule, world(), space(), g.size[0], g.size[1], 1.0);
        break;
      case ShapeKind::Cylinder:
        object = &add<Cylindrical>(Shape::Cylinder, world(), space(), g.size[0], g.size[1], 1.0);
        break;
      case ShapeKind::Plane: object = &add<Plane>(space(), g.plane[0], g.plane[1], g.plane[2], g.plane[3]); break;
    }
    geomIndex_[object->getGeom()] = static_cast<int>(i);
    made.emplace_back(i, object);
    if (g.body >= 0) object->color = bodyColor(g.body);
    if (g.shape == ShapeKind::Plane) continue;
    object->edged = true;
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
  for (size_t b = 0; b < world_.bodies.size(); ++b)
    if (bodies[b]) buildBody(static_cast<int>(b), *bodyOwner_[b]);
  // Offsets last: attach() moved each composite body and re-seated its geoms.
  for (const auto& [i, object] : made) {
    const Geom& g = world_.geoms[i];
    dGeomSetCategoryBits(object->getGeom(), g.category);
    dGeomSetCollideBits(object->getGeom(), g.collide);
    if (g.body < 0 || g.shape == ShapeKind::Plane) continue;
    const bool shared = geomsOfBody[static_cast<size_t>(g.body)] > 1;
    if (!shared && identity(g.position, g.orientation)) continue;
    dGeomSetOffsetPosition(object->getGeom(), g.position[0], g.position[1], g.position[2]);
    const dQuaternion q = {g.orientation[0], g.orientation[1], g.orientation[2], g.orientation[3]};
    dGeomSetOffsetQuaternion(object->getGeom(), q);
  }
}

void WorldFileScene::beforeStep() {
  // An event at t acts before the step that starts at t.
  while (nextEvent_ < world_.events.size() && world_.events[nextEvent_].at <= simulatedTime() + settings().step / 2) {
    const Event& e = world_.events[nextEvent_++];
    const size_t b = static_cast<size_t>(e.body);
    measures_->beforeEvent();
    if (e.kind == EventKind::Drop && !bodyOwner_[b]) {
      std::vector<bool> only(world_.bodies.size(), false);
      only[b] = true;
      buildGeoms(only, false);
      measures_->afterEvent(e.body, bodyOwner_[b]->getBody(), simulatedTime());
    } else if (e.kind == EventKind::Push && bodyOwner_[b]) {
      const dBodyID body = bodyOwner_[b]->getBody();
      const dReal* v = dBodyGetLinearVel(body);
      const double m = world_.bodies[b].mass;
      dBodySetLinearVel(body, v[0] + e.impulse[0] / m, v[1] + e.impulse[1] / m, v[2] + e.impulse[2] / m);
      dBodyEnable(body);
      measures_->afterEvent(e.body, nullptr, simulatedTime());
    }
  }
}

void WorldFileScene::afterStep() { measures_->afterStep(simulatedTime()); }

void WorldFileScene::addMetrics(Metrics& metrics) const {
  if (measures_) measures_->addMetrics(metrics);
  // What an imported file (MJCF) had that the world does not carry.
  if (!world_.notes.empty()) {
    metrics.set("world_note_count", static_cast<double>(world_.notes.size()));
    metrics.setTexts("world_notes", world_.notes);
  }
}

// Bodies that start inside one another are pushed apart by the first step's
// contacts: legal, and a likely slip in a hand-written file, so said once.
void WorldFileScene::warnOfOverlaps() {
  struct Overlaps {
    WorldFileScene* scene;
    static void near(void* data, dGeomID a, dGeomID b) {
      auto* self = static_cast<Overlaps*>(data)->scene;
      const dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
      if ((!ba && !bb) || ba == bb || (ba && bb && dAreConnectedExcluding(ba, bb, dJointTypeContact))) return;
      dContactGeom contacts[16];
      const int n = dCollide(a, b, 16, contacts, sizeof(dContactGeom));
      double depth = 0.0;
      for (int i = 0; i < n; ++i) depth = std::max(depth, static_cast<double>(contacts[i].depth));
      if (depth > OVERLAP_TOLERANCE)
        std::fprintf(stderr, "warning: geoms[%d] and geoms[%d] overlap by %.4g m at t = 0; the first steps push them apart\n",
                     self->geomIndex_.at(a), self->geomIndex_.at(b), depth);
    }
  } overlaps{this};
  dSpaceCollide(space(), &overlaps, &Overlaps::near);
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

// A joint's own ERP and CFM (ball and fixed joints: ODE has none for a hinge's
// or slider's rows, and the reader refuses them there).
dJointID WorldFileScene::buildJoint(const Joint& j) {
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
      break;
    case JointKind::Slider:
      joint = dJointCreateSlider(world(), 0);
      dJointAttach(joint, bodyOf(j.body1), bodyOf(j.body2));
      dJointSetSliderAxis(joint, j.axis[0], j.axis[1], j.axis[2]);
      if (std::isfinite(j.lowStop)) dJointSetSliderParam(joint, dParamLoStop, j.lowStop);
      if (std::isfinite(j.highStop)) dJointSetSliderParam(joint, dParamHiStop, j.highStop);
      break;
    case JointKind::Fixed:
      joint = dJointCreateFixed(world(), 0);
      dJointAttach(joint, bodyOf(j.body1), bodyOf(j.body2));
      dJointSetFixed(joint);
      if (!std::isnan(j.erp)) dJointSetFixedParam(joint, dParamERP, j.erp);
      if (!std::isnan(j.cfm)) dJointSetFixedParam(joint, dParamCFM, j.cfm);
      break;
  }
  return joint;
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

// The bodies and the static geoms that are not planes, each as a sphere
// about its centre wide enough for its largest side.
void WorldFileScene::initialCamera(Camera& camera) const {
  double low[3] = {1e300, 1e300, 1e300}, high[3] = {-1e300, -1e300, -1e300};
  for (const Geom& g : world_.geoms) {
    if (g.shape == ShapeKind::Plane) continue;
    const Vec3& at = g.body < 0 ? g.position : world_.bodies[static_cast<size_t>(g.body)].position;
    const double reach = g.shape == ShapeKind::Box ? std::sqrt(g.size[0] * g.size[0] + g.size[1] * g.size[1] + g.size[2] * g.size[2]) / 2
                                                   : g.size[0] + g.size[1] / 2;
    const double offset = std::sqrt(g.position[0] * g.position[0] + g.position[1] * g.position[1] + g.position[2] * g.position[2]);
    for (size_t k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], at[k] - reach - (g.body < 0 ? 0 : offset));
      high[k] = std::max(high[k], at[k] + reach + (g.body < 0 ? 0 : offset));
    }
  }
  // A chain or pendulum hung from the world swings anywhere within its reach of the anchor.
  for (const Joint& j : world_.joints) {
    if (j.body1 >= 0 && j.body2 >= 0) continue;
    double reach = 0.0;
    for (const Body& b : world_.bodies)
      reach = std::max(reach, std::sqrt(std::pow(b.position[0] - j.anchor[0], 2) + std::pow(b.position[1] - j.anchor[1], 2) +
                                        std::pow(b.position[2] - j.anchor[2], 2)));
    for (size_t k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], j.anchor[k] - reach);
      high[k] = std::max(high[k], j.anchor[k] + reach);
    }
  }
  // A ghost's path over the run (its law's poses), so that the answer and
  // the bodies following it stay in view: a dropped ball's fall to the ground.
  if (ghost_) {
    const double run = world_.duration > 0 ? world_.duration : defaultHeadlessSeconds();
    const int samples = 64;
    for (int i = 0; i <= samples; ++i) {
      const GhostPose pose = ghost_->at(run * i / samples);
      for (const Geom& g : ghost_->shapes()) {
        const double reach = std::sqrt(g.position[0] * g.position[0] + g.position[1] * g.position[1] +
                                       g.position[2] * g.position[2]) +
                             (g.shape == ShapeKind::Box ? std::sqrt(g.size[0] * g.size[0] + g.size[1] * g.size[1] +
                                                                     g.size[2] * g.size[2]) / 2
                                                        : g.size[0] + g.size[1] / 2);
        for (size_t k = 0; k < 3; ++k) {
          low[k] = std::min(low[k], pose.position[k] - reach);
          high[k] = std::max(high[k], pose.position[k] + reach);
        }
      }
    }
  }
  if (low[0] > high[0]) return AbstractWindow::initialCamera(camera);
  const glm::vec3 centre((low[0] + high[0]) / 2, (low[1] + high[1]) / 2, (low[2] + high[2]) / 2);
  const float radius = std::max(0.25f, static_cast<float>(std::sqrt((high[0] - low[0]) * (high[0] - low[0]) +
                                                                    (high[1] - low[1]) * (high[1] - low[1]) +
                                                                    (high[2] - low[2]) * (high[2] - low[2])) / 2));
  // Far enough for the whole sphere to fit the view, from the front and a little above.
  const float distance = radius / std::sin(glm::radians(camera.fieldOfViewDegrees() / 2));
  camera.lookAt(centre + distance * glm::normalize(glm::vec3(0, 0.35f, 1)), centre);
}

std::string WorldFileScene::fileTitle(const std::string& path) const {
  const std::string name = path.substr(path.find_last_of("/\\") + 1);
  if (!world_.title.empty()) return world_.title + " (" + name + ")";
  return name;
}

void WorldFileScene::addHudLines(std::vector<std::string>& lines) const {
  auto count = [](size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); };
  // The measures first, on one line: the compact HUD shows the first line,
  // and every measure belongs in it.
  if (measures_) {
    std::vector<std::string> measured;
    measures_->addHudLines(measured);
    std::string joined;
    for (const std::string& line : measured) joined += (joined.empty() ? "" : "   ") + line;
    if (!joined.empty()) lines.push_back(joined);
  }
  lines.push_back("world file" + (world_.scene.empty() ? std::string() : " from " + world_.scene) + ": " +
                  count(world_.bodies.size(), "body", "bodies") + ", " + count(world_.geoms.size(), "geom", "geoms") +
                  ", " + count(world_.joints.size(), "joint", "joints"));
}

bool WorldFileScene::plotValue(double& value) const {
  return (measures_ && measures_->plotValue(value)) || AbstractWindow::plotValue(value);
}

// Asked before the scene is built: from the file.
std::string WorldFileScene::plotLabel() const {
  for (const Measure& m : world_.measures)
    if (m.kind == MeasureKind::Energy) return "total energy (J)";
  return AbstractWindow::plotLabel();
}

}  // namespace odelab::world
