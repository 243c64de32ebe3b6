// SDF in (WorldFromSdf.h): SDFormat parses the file and resolves its frames
// (poses relative_to other frames, axes expressed_in them), and this file
// reads the parsed sdf::World into a World. SDF's z-up frame is turned to
// this format's y-up one: (x, y, z) -> (x, z, -y), a rotation of -90 degrees
// about x: exact for every vector, orientations turned by its quaternion.
// Where SDF leaves the contact between two collisions to the simulator
// (friction, bounce of a pair), the rules are those of Gazebo's ODE engine,
// which SDF's <surface><friction><ode> and <bounce> elements are written for.
#include "WorldFromSdf.h"

#include <sdf/Box.hh>
#include <sdf/Capsule.hh>
#include <sdf/Collision.hh>
#include <sdf/Console.hh>
#include <sdf/Cylinder.hh>
#include <sdf/Element.hh>
#include <sdf/Geometry.hh>
#include <sdf/Joint.hh>
#include <sdf/JointAxis.hh>
#include <sdf/Link.hh>
#include <sdf/Model.hh>
#include <sdf/Physics.hh>
#include <sdf/Plane.hh>
#include <sdf/Root.hh>
#include <sdf/Sphere.hh>
#include <sdf/Surface.hh>
#include <sdf/World.hh>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>

#include "WorldJson.h"

namespace odelab::world {

namespace {

using Pose = ignition::math::Pose3d;
using Vector = ignition::math::Vector3d;
using Rotation = ignition::math::Quaterniond;

// 0.0 - y, not -y: a 0 stays 0 rather than -0 in the exported file.
Vec3 yUp(const Vector& v) { return {v.X(), v.Z(), 0.0 - v.Y()}; }

// The rotation yUp applies, as a quaternion: about x by -90 degrees.
Quat yUpQuat(const Rotation& q) {
  const double half = std::sqrt(0.5);
  const Rotation turned = Rotation(half, -half, 0, 0) * q;
  return {turned.W(), turned.X(), turned.Y(), turned.Z()};
}

// A body's frame: the link's, relabelled as the world is (its local x, y, z
// turned by the same rotation), so that a link unturned in SDF's world is
// unturned here: its orientation is the rotation conjugated, t q t^-1.
Quat yUpBodyQuat(const Rotation& q) {
  const double half = std::sqrt(0.5);
  const Rotation turn(half, -half, 0, 0);
  const Rotation turned = turn * q * turn.Inverse();
  return {turned.W(), turned.X(), turned.Y(), turned.Z()};
}

// The pose `local` given in the frame `frame`, in the frame `frame` is given in.
Pose compose(const Pose& frame, const Pose& local) {
  return Pose(frame.Pos() + frame.Rot().RotateVector(local.Pos()), frame.Rot() * local.Rot());
}

std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// A child element's value where the file may not have it: SDF's own default
// (from its description of the element) when absent. The parsed elements are
// the parser's copies, so filling one in changes nothing in the file.
template <typename T>
T valueAt(sdf::ElementPtr element, std::initializer_list<const char*> path, T fallback) {
  for (const char* name : path) {
    if (!element || !element->HasElementDescription(name)) return fallback;
    element = element->GetElement(name);
  }
  return element ? element->Get<T>() : fallback;
}

bool has(const sdf::ElementPtr& element, const char* name) { return element && element->HasElement(name); }

// What a collision brings to a contact, as SDF writes it.
struct Contact {
  double mu = 1.0;
  double restitution = 0.0;
  double threshold = 100000.0;  // m/s: SDF's default, never reached
};

// A moving link, once it is one of the world's bodies.
struct Placed {
  int body = -1;  // -1: a link of a static model
  Pose frame;     // the link's frame in the world (z up)
  Vector com;     // its centre of mass in the world (z up)
  Vector comInLink;  // the same in the link's frame
};

class Translation {
 public:
  Translation(const sdf::World& world, std::string path) : sdf_(world), path_(std::move(path)) {}

  World run() {
    refuseWholeWorldParts();
    settings();
    for (uint64_t m = 0; m < sdf_.ModelCount(); ++m) model(*sdf_.ModelByIndex(m));
    for (uint64_t m = 0; m < sdf_.ModelCount(); ++m) joints(*sdf_.ModelByIndex(m));
    surfaces();
    standingNotes();
    return std::move(world_);
  }

 private:
  [[noreturn]] void refuse(const std::string& what) const {
    throw WorldFileError(path_ + ": SDF: " + what + " (doc/world-format.md, \"SDF\", says what is read)");
  }

  void note(const std::string& what) {
    if (std::find(world_.notes.begin(), world_.notes.end(), what) == world_.notes.end()) world_.notes.push_back(what);
  }

  void refuseWholeWorldParts() const {
    const sdf::ElementPtr element = sdf_.Element();
    if (has(element, "state"))
      refuse("<world> has a <state>: this reader takes the poses the models are written with, not a saved state");
    if (sdf_.ActorCount() > 0) refuse(std::to_string(sdf_.ActorCount()) + " <actor>(s): this format has no scripted bodies");
  }

  void settings() {
    world_.scene = "sdf";
    world_.title = sdf_.Name().empty() ? "SDF world" : sdf_.Name();
    world_.settings.gravity = yUp(sdf_.Gravity());
    const sdf::Physics* physics = sdf_.PhysicsDefault();
    if (!physics) refuse("<world> has no <physics>");
    world_.settings.step = physics->MaxStepSize();
    if (physics->EngineType() != "ode")
      note("<physics type=\"" + physics->EngineType() + "\">: run with its <ode> settings all the same (SDF's defaults where absent)");
    // SDF's <physics><ode> is ODE's own world: every value maps to this
    // format's settings, SDF's defaults where the file is silent.
    const sdf::ElementPtr element = physics->Element();
    Settings& s = world_.settings;
    const std::string solver = valueAt<std::string>(element, {"ode", "solver", "type"}, "quick");
    if (solver != "quick" && solver != "world")
      refuse("<physics><ode><solver><type> \"" + solver + "\": ODE's solvers are \"quick\" and \"world\"");
    s.quickStep = solver == "quick";
    s.iterations = valueAt<int>(element, {"ode", "solver", "iters"}, 50);
    s.sorW = valueAt<double>(element, {"ode", "solver", "sor"}, 1.3);
    s.cfm = valueAt<double>(element, {"ode", "constraints", "cfm"}, 0.0);
    s.erp = valueAt<double>(element, {"ode", "constraints", "erp"}, 0.2);
    s.contactMaxCorrectingVelocity = valueAt<double>(element, {"ode", "constraints", "contact_max_correcting_vel"}, 100.0);
    s.contactSurfaceLayer = valueAt<double>(element, {"ode", "constraints", "contact_surface_layer"}, 0.001);
    s.maxContacts = valueAt<int>(element, {"max_contacts"}, 20);
    if (valueAt<std::string>(element, {"ode", "solver", "friction_model"}, "pyramid_model") != "pyramid_model")
      note("<physics><ode><solver><friction_model> not carried: friction is ODE's pyramid, as SDF's default");
    if (valueAt<int>(element, {"ode", "solver", "precon_iters"}, 0) != 0 ||
        valueAt<bool>(element, {"ode", "solver", "use_dynamic_moi_rescaling"}, false))
      note("<physics><ode><solver> precon_iters and use_dynamic_moi_rescaling not carried (Gazebo's own additions to ODE)");
    if (sdf_.LightCount() > 0) note(std::to_string(sdf_.LightCount()) + " <light>(s) not carried: nothing is drawn from the file");
    if (has(sdf_.Element(), "plugin")) note("<world> <plugin>s not carried: nothing but the physics runs");
  }

  // A model's links become bodies (or static geoms, for a static model) and
  // their collisions geoms, link by link: the exporter numbers bodies as it
  // meets them through their geoms, and keeps the file's order so.
  void model(const sdf::Model& model) {
    const std::string name = "model '" + model.Name() + "'";
    if (model.ModelCount() > 0) refuse(name + " has nested <model>s: this reader takes one level of models");
    if (model.InterfaceModelCount() > 0) refuse(name + " includes a model through a custom parser");
    if (has(model.Element(), "plugin")) note("<plugin>s not carried: nothing drives the joints or links");
    if (!model.Static() && model.AllowAutoDisable())
      note("<allow_auto_disable> not carried: no body is put to sleep (Gazebo's thresholds are its own)");
    Pose placed;
    const sdf::Errors errors = model.SemanticPose().Resolve(placed);
    if (!errors.empty()) refuse(name + "'s pose: " + errors[0].Message());
    placements_[model.Name()] = placed;
    // SDF's <self_collide> false (its default): a model's links do not touch
    // each other. A model of several moving links is given a category bit of
    // its own, and collides with everything but that bit.
    std::uint32_t ownBit = 0;
    if (!model.Static() && !model.SelfCollide() && model.LinkCount() > 1) {
      if (selfBits_ == 32) refuse(name + ": more than 32 models of several links without <self_collide>: this format has 32 category bits");
      ownBit = 1u << selfBits_++;
    }
    for (uint64_t l = 0; l < model.LinkCount(); ++l) link(model, *model.LinkByIndex(l), placed, ownBit);
  }

  void link(const sdf::Model& model, const sdf::Link& link, const Pose& modelPose, std::uint32_t ownBit) {
    const std::string name = "link '" + model.Name() + "::" + link.Name() + "'";
    Pose local;
    const sdf::Errors errors = link.SemanticPose().Resolve(local, "__model__");
    if (!errors.empty()) refuse(name + "'s pose: " + errors[0].Message());
    Placed placed;
    placed.frame = compose(modelPose, local);
    const ignition::math::Inertiald& inertial = link.Inertial();
    placed.comInLink = inertial.Pose().Pos();
    placed.com = placed.frame.Pos() + placed.frame.Rot().RotateVector(placed.comInLink);
    const sdf::ElementPtr element = link.Element();
    if (!model.Static()) {
      const double mass = inertial.MassMatrix().Mass();
      if (!(mass > 0)) refuse(name + " moves and has mass " + number(mass) + ": this format needs a mass above 0");
      Body body;
      body.mass = mass;
      // About the centre of mass, in the link's frame (SDFormat turns the
      // <inertial> pose's rotation into it): the link's frame is the body's.
      // In the body's frame, relabelled as yUp does: (x, y, z) -> (x, z, -y).
      const ignition::math::Matrix3d moi = inertial.Moi();
      body.inertia = {moi(0, 0), moi(2, 2), moi(1, 1), moi(0, 2), 0.0 - moi(0, 1), 0.0 - moi(2, 1)};
      body.position = yUp(placed.com);
      body.orientation = yUpBodyQuat(placed.frame.Rot());
      body.gravity = valueAt<bool>(element, {"gravity"}, true);
      body.kinematic = valueAt<bool>(element, {"kinematic"}, false);
      if (valueAt<double>(element, {"velocity_decay", "linear"}, 0.0) != 0 ||
          valueAt<double>(element, {"velocity_decay", "angular"}, 0.0) != 0)
        refuse(name + " has a <velocity_decay>: this format has no damping of a body's velocity");
      if (valueAt<bool>(element, {"enable_wind"}, false) && sdf_.WindLinearVelocity() != Vector::Zero)
        refuse(name + " is blown by the world's <wind>: this format has no medium forces");
      placed.body = static_cast<int>(world_.bodies.size());
      world_.bodies.push_back(body);
    }
    links_[model.Name() + "::" + link.Name()] = placed;
    if (link.VisualCount() > 0) note("<visual>s not carried: each body is drawn as its collision shapes");
    if (link.SensorCount() > 0 || link.LightCount() > 0 || link.ParticleEmitterCount() > 0)
      note("link <sensor>s, <light>s and <particle_emitter>s not carried");
    for (uint64_t c = 0; c < link.CollisionCount(); ++c) collision(name, *link.CollisionByIndex(c), placed, ownBit);
    if (placed.body >= 0 && link.CollisionCount() == 0) {
      // The format finds a body through its geoms: a link without a
      // collision carries a sphere that touches nothing.
      Geom marker;
      marker.shape = ShapeKind::Sphere;
      marker.size = {1e-3, 0, 0};
      marker.body = placed.body;
      marker.category = 0;
      marker.collide = 0;
      contacts_.push_back(std::nullopt);
      world_.geoms.push_back(marker);
    }
  }

  void collision(const std::string& linkName, const sdf::Collision& collision, const Placed& placed, std::uint32_t ownBit) {
    const std::string name = "collision '" + collision.Name() + "' of " + linkName;
    Pose inLink;
    const sdf::Errors errors = collision.SemanticPose().Resolve(inLink);
    if (!errors.empty()) refuse(name + "'s pose: " + errors[0].Message());
    const Pose pose = compose(placed.frame, inLink);
    const sdf::Geometry& shape = *collision.Geom();
    Geom geom;
    geom.body = placed.body;
    switch (shape.Type()) {
      case sdf::GeometryType::BOX: {
        const Vector size = shape.BoxShape()->Size();
        geom.shape = ShapeKind::Box;
        geom.size = {size.X(), size.Y(), size.Z()};
        break;
      }
      case sdf::GeometryType::SPHERE:
        geom.shape = ShapeKind::Sphere;
        geom.size = {shape.SphereShape()->Radius(), 0, 0};
        break;
      // Both along local z, the length that of the cylindrical part, as here.
      case sdf::GeometryType::CYLINDER:
        geom.shape = ShapeKind::Cylinder;
        geom.size = {shape.CylinderShape()->Radius(), shape.CylinderShape()->Length(), 0};
        break;
      case sdf::GeometryType::CAPSULE:
        geom.shape = ShapeKind::Capsule;
        geom.size = {shape.CapsuleShape()->Radius(), shape.CapsuleShape()->Length(), 0};
        break;
      case sdf::GeometryType::PLANE: geom.shape = ShapeKind::Plane; break;
      default:
        refuse(name + " is a <" + geometryName(shape.Type()) +
               ">: this format has box, sphere, cylinder, capsule and plane only");
    }
    if (geom.shape == ShapeKind::Plane) {
      if (placed.body >= 0) refuse(name + " is a plane on a moving link: a plane is static here");
      // SDF's plane passes through the collision's origin, its normal given
      // in the collision's frame; its <size> only bounds what is drawn.
      const Vec3 n = yUp(pose.Rot().RotateVector(shape.PlaneShape()->Normal().Normalized()));
      const Vec3 p = yUp(pose.Pos());
      geom.plane = {n[0], n[1], n[2], n[0] * p[0] + n[1] * p[1] + n[2] * p[2]};
    } else if (placed.body < 0) {
      geom.position = yUp(pose.Pos());
      geom.orientation = yUpQuat(pose.Rot());
    } else {
      // On a body: relative to its centre of mass, in its frame (the link's,
      // relabelled): taken in the link's frame as SDF gives it, so that no
      // rounding of the link's own turn comes in.
      geom.position = yUp(inLink.Pos() - placed.comInLink);
      geom.orientation = yUpQuat(inLink.Rot());
    }
    // Gazebo's rule: two collisions touch when their bitmasks share a bit,
    // which is ODE's category/collide rule with both set to the bitmask.
    const sdf::Surface* surface = collision.Surface();
    const std::uint32_t bitmask =
        surface && surface->Contact() ? surface->Contact()->CollideBitmask() : std::uint32_t{0xffff};
    if (ownBit) {
      if (bitmask != 0xff && bitmask != 0xffff)
        refuse(name + " sets a <collide_bitmask> in a model without <self_collide>: this format cannot hold both");
      geom.category = ownBit;
      geom.collide = ~ownBit;
    } else if (bitmask != 0xff && bitmask != 0xffff) {
      if (selfBits_ > 0) refuse(name + " sets a <collide_bitmask> beside a model without <self_collide>: this format cannot hold both");
      geom.category = geom.collide = bitmask;
    }
    const sdf::ElementPtr element = surface ? surface->Element() : nullptr;
    if (valueAt<bool>(element, {"contact", "collide_without_contact"}, false)) {
      note("<collide_without_contact> collisions touch nothing here (they only report contacts in Gazebo)");
      geom.category = geom.collide = 0;
    }
    contacts_.push_back(contactOf(element));
    world_.geoms.push_back(geom);
  }

  Contact contactOf(const sdf::ElementPtr& surface) {
    Contact contact;
    contact.mu = valueAt<double>(surface, {"friction", "ode", "mu"}, 1.0);
    const double mu2 = valueAt<double>(surface, {"friction", "ode", "mu2"}, 1.0);
    if (mu2 != contact.mu) note("<mu2> not carried: friction is <mu> in every direction");
    if (valueAt<double>(surface, {"friction", "ode", "slip1"}, 0.0) != 0 ||
        valueAt<double>(surface, {"friction", "ode", "slip2"}, 0.0) != 0)
      note("<slip1> and <slip2> not carried: contacts do not slip by force");
    if (valueAt<Vector>(surface, {"friction", "ode", "fdir1"}, Vector::Zero) != Vector::Zero)
      note("<fdir1> not carried: friction has no preferred direction here");
    if (has(surface, "friction") && has(surface->GetElement("friction"), "torsional"))
      note("<torsional> friction not carried: contacts have sliding friction only");
    contact.restitution = valueAt<double>(surface, {"bounce", "restitution_coefficient"}, 0.0);
    contact.threshold = valueAt<double>(surface, {"bounce", "threshold"}, 100000.0);
    if (contact.mu < 0) refuse("a <mu> of " + number(contact.mu) + ": friction cannot be negative");
    if (contact.restitution < 0 || contact.restitution > 1)
      refuse("a <restitution_coefficient> of " + number(contact.restitution) + ": it lies in [0, 1]");
    return contact;
  }

  static const char* geometryName(sdf::GeometryType type) {
    switch (type) {
      case sdf::GeometryType::MESH: return "mesh";
      case sdf::GeometryType::HEIGHTMAP: return "heightmap";
      case sdf::GeometryType::ELLIPSOID: return "ellipsoid";
      case sdf::GeometryType::EMPTY: return "empty";
      default: return "geometry unknown to this reader";
    }
  }

  void joints(const sdf::Model& model) {
    if (model.Static()) return;  // nothing in it moves
    const Pose& modelPose = placements_[model.Name()];
    for (uint64_t j = 0; j < model.JointCount(); ++j) joint(model, *model.JointByIndex(j), modelPose);
  }

  // A joint's link, by the name the joint gives: "world", or one in the model.
  int bodyOf(const sdf::Model& model, const std::string& link, const std::string& joint) const {
    if (link == "world") return -1;
    const auto found = links_.find(model.Name() + "::" + link);
    if (found == links_.end()) refuse(joint + " joins '" + link + "', which is not a link of its model");
    return found->second.body;
  }

  void joint(const sdf::Model& model, const sdf::Joint& sdfJoint, const Pose& modelPose) {
    const std::string name = "joint '" + model.Name() + "::" + sdfJoint.Name() + "'";
    Joint joint;
    switch (sdfJoint.Type()) {
      case sdf::JointType::REVOLUTE:
      case sdf::JointType::CONTINUOUS: joint.kind = JointKind::Hinge; break;
      case sdf::JointType::PRISMATIC: joint.kind = JointKind::Slider; break;
      case sdf::JointType::BALL: joint.kind = JointKind::Ball; break;
      case sdf::JointType::FIXED: joint.kind = JointKind::Fixed; break;
      default: refuse(name + " is of a type this format has not (it has revolute, continuous, prismatic, ball and fixed)");
    }
    // The child first: ODE's hinge angle and slider position then grow as
    // SDF's joint position does (the child's turn or travel relative to the
    // parent along the axis), so the limits map as they are written.
    joint.body1 = bodyOf(model, sdfJoint.ChildLinkName(), name);
    joint.body2 = bodyOf(model, sdfJoint.ParentLinkName(), name);
    if (joint.body1 < 0 && joint.body2 < 0) return;  // between static links: nothing moves
    Pose local;
    sdf::Errors errors = sdfJoint.SemanticPose().Resolve(local, "__model__");
    if (!errors.empty()) refuse(name + "'s pose: " + errors[0].Message());
    joint.anchor = yUp(compose(modelPose, local).Pos());
    const sdf::JointAxis* axis = sdfJoint.Axis(0);
    if (joint.kind == JointKind::Hinge || joint.kind == JointKind::Slider) {
      if (!axis) refuse(name + " has no <axis>");
      Vector xyz;
      errors = axis->ResolveXyz(xyz, "__model__");
      if (!errors.empty()) refuse(name + "'s axis: " + errors[0].Message());
      joint.axis = yUp(modelPose.Rot().RotateVector(xyz).Normalized());
      if (axis->Damping() != 0) refuse(name + " has damping " + number(axis->Damping()) + ": this format has no joint damping");
      if (axis->Friction() != 0) refuse(name + " has friction " + number(axis->Friction()) + ": this format has no joint friction");
      if (axis->SpringStiffness() != 0)
        refuse(name + " has spring_stiffness " + number(axis->SpringStiffness()) + ": this format has no joint springs");
      // SDF writes "no limit" as +-1e16.
      if (sdfJoint.Type() != sdf::JointType::CONTINUOUS) {
        if (axis->Lower() > -1e16) joint.lowStop = axis->Lower();
        if (axis->Upper() < 1e16) joint.highStop = axis->Upper();
      }
      // Unbounded when absent (SDFormat's infinity) or negative (SDF's -1).
      if ((std::isfinite(axis->Effort()) && axis->Effort() >= 0) ||
          (std::isfinite(axis->MaxVelocity()) && axis->MaxVelocity() >= 0))
        note("<limit> effort and velocity not carried: they bound a motor, and nothing drives the joints here");
      if (axis->Stiffness() != 1e8 || axis->Dissipation() != 1)
        note("<limit> stiffness and dissipation not carried: the stops are stiff by the world's ERP and CFM");
    } else if (axis) {
      note("an <axis> of a ball or fixed joint not carried: it has no use there");
    }
    if (sdfJoint.Axis(1)) note("a second <axis> not carried");
    if (has(sdfJoint.Element(), "physics")) note("joint <physics> (its own cfm, erp, suspension) not carried");
    world_.joints.push_back(joint);
  }

  // Gazebo's ODE rule for a pair: the smaller of the two mu, the larger
  // restitution, the smaller bounce threshold. One surface per value a pair
  // takes, the most used as the default.
  void surfaces() {
    std::vector<PairSurface> pairs;
    std::vector<int> uses;
    for (int a = 0; a < static_cast<int>(world_.geoms.size()); ++a)
      for (int b = a + 1; b < static_cast<int>(world_.geoms.size()); ++b) {
        const auto& ca = contacts_[static_cast<size_t>(a)];
        const auto& cb = contacts_[static_cast<size_t>(b)];
        if (!ca || !cb || !world_.mayTouch(a, b)) continue;
        const Surface surface = pairSurface(*ca, *cb);
        int index = static_cast<int>(std::find(world_.surfaces.begin(), world_.surfaces.end(), surface) - world_.surfaces.begin());
        if (index == static_cast<int>(world_.surfaces.size())) {
          world_.surfaces.push_back(surface);
          uses.push_back(0);
        }
        ++uses[static_cast<size_t>(index)];
        pairs.push_back({a, b, index});
      }
    if (world_.surfaces.empty()) {
      world_.surfaces.push_back(pairSurface(Contact{}, Contact{}));
      uses.push_back(0);
    }
    world_.defaultSurface = static_cast<int>(std::max_element(uses.begin(), uses.end()) - uses.begin());
    for (const PairSurface& pair : pairs)
      if (pair.surface != world_.defaultSurface) world_.pairSurfaces.push_back(pair);
  }

  static Surface pairSurface(const Contact& a, const Contact& b) {
    Surface surface;
    surface.mu = std::min(a.mu, b.mu);
    surface.approx1 = true;  // Gazebo's ODE friction pyramid: mu a coefficient, not a force in newtons
    const double restitution = std::max(a.restitution, b.restitution);
    if (restitution > 0) {
      surface.bounce = true;
      surface.restitution = restitution;
      surface.bounceVelocity = std::min(a.threshold, b.threshold);
    }
    return surface;
  }

  void standingNotes() {
    note("surface <contact><ode> kp, kd, soft_cfm, soft_erp, max_vel and min_depth not carried: contacts are stiff by "
         "the world's ERP and CFM and its contact_surface_layer");
  }

  const sdf::World& sdf_;
  std::string path_;
  World world_;
  std::map<std::string, Pose> placements_;  // per model name: its pose in the world
  std::map<std::string, Placed> links_;     // per "model::link"
  std::vector<std::optional<Contact>> contacts_;  // per world geom: its surface, none for a marker sphere
  int selfBits_ = 0;  // category bits given to models without <self_collide>
};

// SDFormat's console, made once: on its making it opens a log file under
// $HOME/.sdformat, which a program that writes only the files it is asked
// for must not do; with HOME at a folder that cannot exist it logs nothing.
// Its messages (an XML parse error's line, which its Errors do not carry)
// go to `messages` rather than to stderr, for the refusal to quote.
std::ostringstream& sdformatMessages() {
  static std::ostringstream messages;
  static const bool made = [] {
    const char* home = std::getenv("HOME");
    const std::string saved = home ? home : "";
    setenv("HOME", "/nonexistent/odelab-no-sdformat-log", 1);
    sdf::Console::Instance()->GetMsgStream().SetStream(&messages);
    if (home) setenv("HOME", saved.c_str(), 1); else unsetenv("HOME");
    return true;
  }();
  (void)made;
  return messages;
}

// SDFormat's console text, its colour codes and line breaks taken out.
std::string plain(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\x1b') {
      while (i < text.size() && text[i] != 'm') ++i;
      continue;
    }
    const char c = text[i] == '\n' || text[i] == '\r' ? ' ' : text[i];
    if (!(c == ' ' && !out.empty() && out.back() == ' ')) out += c;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

}  // namespace

World worldFromSdf(const std::string& path) {
  std::ostringstream& messages = sdformatMessages();
  messages.str("");
  sdf::Root root;
  const sdf::Errors errors = root.Load(path);
  if (!errors.empty()) {
    std::string said;
    for (const sdf::Error& error : errors) said += (said.empty() ? "" : "; ") + error.Message();
    const std::string console = plain(messages.str());
    throw WorldFileError(path + ": SDFormat refused it: " + said + (console.empty() ? "" : " (" + console + ")"));
  }
  if (root.WorldCount() != 1)
    throw WorldFileError(path + ": SDF: " + std::to_string(root.WorldCount()) +
                         " <world>s: this reader takes a file of one <world> (doc/world-format.md, \"SDF\")");
  World world = Translation(*root.WorldByIndex(0), path).run();
  // Through this format's own reader: its ranges and physics checks
  // (positive-definite inertia, unit normals) hold the translation too.
  const std::vector<std::string> notes = world.notes;
  try {
    world = worldFromJson(worldToJson(world));
  } catch (const WorldFileError& error) {
    throw WorldFileError(path + ": SDF as translated: " + error.what());
  }
  world.notes = notes;
  return world;
}

}  // namespace odelab::world
