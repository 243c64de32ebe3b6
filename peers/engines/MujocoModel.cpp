#include "MujocoModel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>
#include <sstream>
#include <utility>

#include "MujocoContacts.h"

namespace odelab::engines::mujoco {

namespace {

using world::Body;
using world::EngineError;
using world::Geom;
using world::Joint;
using world::JointKind;
using world::ShapeKind;
using world::World;

// Two connect constraints this far apart along a hinge's axis hold a hinge
// that closes a loop: together they leave only the turn about the axis.
constexpr double HINGE_SPAN = 1.0;  // m
// A stop at infinity on one side only: MuJoCo's range takes two numbers.
constexpr double NO_STOP = 1e10;

std::string say(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}
std::string vec(const Vec3& v) { return num(v[0]) + ' ' + num(v[1]) + ' ' + num(v[2]); }
std::string quat(const Quat& q) { return num(q[0]) + ' ' + num(q[1]) + ' ' + num(q[2]) + ' ' + num(q[3]); }
std::string poseAttributes(const Pose& pose) {
  return " pos=\"" + vec(pose.position) + "\" quat=\"" + quat(normalized(pose.orientation)) + "\"";
}

bool hasStops(const Joint& joint) {
  return joint.lowStop <= joint.highStop && (std::isfinite(joint.lowStop) || std::isfinite(joint.highStop));
}
std::string range(const Joint& joint) {
  const double low = std::isfinite(joint.lowStop) ? joint.lowStop : -NO_STOP;
  const double high = std::isfinite(joint.highStop) ? joint.highStop : NO_STOP;
  return " limited=\"true\" range=\"" + num(low) + ' ' + num(high) + "\"";
}

class Writer {
 public:
  explicit Writer(const ModelRequest& r) : r_(r), w_(r.world), best_(r.setting == world::EngineSetting::Best) {}

  ModelText write() {
    const double h = w_.settings.step;
    stiff_ = num(BEST_TIME_CONSTANT_STEPS * h) + " 1";
    const ContactParams contact = contactOf(w_.surfaces[static_cast<size_t>(w_.defaultSurface)], r_.setting, h, losses_);
    text_.rk4 = best_ && wantsRk4();
    const bool elliptic = best_ || highFriction();
    s_ << "<mujoco model=\"odelab-world\">\n  <compiler angle=\"radian\"/>\n"
       << "  <option timestep=\"" << num(h) << "\" gravity=\"" << vec(w_.settings.gravity) << "\" integrator=\""
       << (text_.rk4 ? "RK4" : "Euler") << "\"" << (elliptic ? " cone=\"elliptic\"" : "") << "/>\n"
       << "  <size nconmax=\"" << r_.nconmax << "\" njmax=\"" << r_.njmax << "\"/>\n"
       << "  <default><geom condim=\"" << contact.condim << "\" friction=\"" << geomFriction(contact.mu) << "\""
       << (contact.solref.empty() ? "" : " solref=\"" + contact.solref + "\"")
       << (contact.solimp.empty() ? "" : " solimp=\"" + contact.solimp + "\"") << "/></default>\n"
       << "  <worldbody>\n";
    for (size_t g = 0; g < w_.geoms.size(); ++g)
      if (w_.geoms[g].body < 0) writeGeom(static_cast<int>(g), "    ");
    for (const int root : r_.layout.roots) writeBody(root, "    ");
    s_ << "  </worldbody>\n";
    writeContacts();
    writeLoops();
    s_ << "</mujoco>\n";
    noteSettings();
    for (std::string& note : notesOf(losses_, r_.setting)) notes_.push_back(std::move(note));
    text_.xml = s_.str();
    text_.notes = std::move(notes_);
    return std::move(text_);
  }

 private:
  // Best integrates with RK4 where the old mujoco_lab measured it better:
  // a pendulum (a hinge or slider) and a spring contact (a bounce).
  bool wantsRk4() const {
    for (const Joint& joint : w_.joints)
      if (joint.kind == JointKind::Hinge || joint.kind == JointKind::Slider) return true;
    if (bounces(w_.surfaces[static_cast<size_t>(w_.defaultSurface)])) return true;
    for (const world::PairSurface& pair : w_.pairSurfaces)
      if (bounces(w_.surfaces[static_cast<size_t>(pair.surface)])) return true;
    return false;
  }

  // MuJoCo's default friction cone, a pyramid, softens the normal contact
  // by 1 + mu^2: a box resting on a box sank 0.6 mm at mu = 2, 7 mm at mu = 4
  // and fell through at mu = 10 (MuJoCo 2.2.2, its default solref). An
  // elliptic cone keeps the normal contact whatever the friction.
  bool highFriction() {
    double most = w_.surfaces[static_cast<size_t>(w_.defaultSurface)].mu;
    for (const world::PairSurface& pair : w_.pairSurfaces)
      most = std::max(most, w_.surfaces[static_cast<size_t>(pair.surface)].mu);
    if (most <= 1.0) return false;
    if (!best_)
      notes_.push_back("friction above 1 with MuJoCo's default pyramidal friction cone would soften the normal contact "
                       "by 1 + mu^2 (a box on a box fell through at mu = 10): the cones are elliptic");
    return true;
  }

  bool geomAlive(int g) const {
    const int body = w_.geoms[static_cast<size_t>(g)].body;
    return body < 0 || !w_.bodies[static_cast<size_t>(body)].removed;
  }

  void writeGeom(int g, const std::string& indent) {
    const Geom& geom = w_.geoms[static_cast<size_t>(g)];
    s_ << indent << "<geom name=\"" << geomName(g) << "\"";
    switch (geom.shape) {
      case ShapeKind::Box:
        s_ << " type=\"box\" size=\"" << vec(scale(geom.size, 0.5)) << "\"";
        break;
      case ShapeKind::Sphere:
        s_ << " type=\"sphere\" size=\"" << num(geom.size[0]) << "\"";
        break;
      case ShapeKind::Capsule:
      case ShapeKind::Cylinder:  // both along local z, as ODE's
        s_ << " type=\"" << (geom.shape == ShapeKind::Capsule ? "capsule" : "cylinder") << "\" size=\""
           << num(geom.size[0]) << ' ' << num(geom.size[1] / 2) << "\"";
        break;
      case ShapeKind::Plane: {
        // a x + b y + c z = d: MuJoCo's plane is its frame's z = 0, infinite.
        const Vec3 n{geom.plane[0], geom.plane[1], geom.plane[2]};
        const Vec3 unit = scale(n, 1.0 / norm(n));
        s_ << " type=\"plane\" size=\"0 0 1\" pos=\"" << vec(scale(unit, geom.plane[3] / norm(n))) << "\" zaxis=\""
           << vec(unit) << "\"";
        break;
      }
    }
    if (geom.shape != ShapeKind::Plane) s_ << poseAttributes({geom.position, geom.orientation});
    // ODE's rule and MuJoCo's are the same: either's category meets the other's collide bits.
    s_ << " contype=\"" << static_cast<std::int32_t>(geom.category) << "\" conaffinity=\""
       << static_cast<std::int32_t>(geom.collide) << "\"/>\n";
  }

  void writeBody(int b, const std::string& indent) {
    const Body& body = w_.bodies[static_cast<size_t>(b)];
    const Mount& mount = r_.layout.bodies[static_cast<size_t>(b)];
    s_ << indent << "<body name=\"" << bodyName(b) << "\"" << poseAttributes(mount.reference)
       << (mount.kind == Mount::Kind::Mocap ? " mocap=\"true\"" : "") << ">\n";
    const std::string in = indent + "  ";
    if (mount.kind == Mount::Kind::Free) s_ << in << "<freejoint/>\n";
    if (mount.kind == Mount::Kind::Joint) writeTreeJoint(w_.joints[static_cast<size_t>(mount.joint)], mount, in);
    // The exact mass and inertia about the centre of mass (the body's origin).
    const auto& i = body.inertia;
    s_ << in << "<inertial pos=\"0 0 0\" mass=\"" << num(body.mass) << "\" fullinertia=\"" << num(i[0]) << ' '
       << num(i[1]) << ' ' << num(i[2]) << ' ' << num(i[3]) << ' ' << num(i[4]) << ' ' << num(i[5]) << "\"/>\n";
    for (size_t g = 0; g < w_.geoms.size(); ++g)
      if (w_.geoms[g].body == b) writeGeom(static_cast<int>(g), in);
    for (const int child : r_.layout.children[static_cast<size_t>(b)]) writeBody(child, in);
    s_ << indent << "</body>\n";
    noteBody(body);
  }

  void writeTreeJoint(const Joint& joint, const Mount& mount, const std::string& in) {
    notes_.push_back(
        "joints are MuJoCo joints in generalized coordinates (a body's freedom relative to its parent body): they "
        "cannot come apart, so their error is 0 where ODE's is not");
    noteJointSoftness(joint);
    switch (joint.kind) {
      case JointKind::Ball:
        s_ << in << "<joint type=\"ball\" pos=\"" << vec(mount.anchor) << "\"/>\n";
        return;
      case JointKind::Hinge:
      case JointKind::Slider:
        s_ << in << "<joint type=\"" << (joint.kind == JointKind::Hinge ? "hinge" : "slide") << "\" pos=\""
           << vec(mount.anchor) << "\" axis=\"" << vec(mount.axis) << "\"";
        if (hasStops(joint)) {
          s_ << range(joint) << (best_ ? " solreflimit=\"" + stiff_ + "\" solimplimit=\"" + BEST_SOLIMP + "\"" : "");
          notes_.push_back(std::string("joint stops are MuJoCo's soft limits (solref ") +
                           (best_ ? stiff_ : "0.02 1") + "), not ODE's stop ERP and CFM");
        }
        s_ << "/>\n";
        return;
      case JointKind::Fixed:  // a child without a joint is welded to its parent
        return;
    }
  }

  void noteJointSoftness(const Joint& joint) {
    if (!std::isnan(joint.erp) || !std::isnan(joint.cfm))
      notes_.push_back("a joint's own ERP and CFM are not applied: MuJoCo's joints have no error to correct, and its "
                       "constraints are softened by solref and solimp instead");
  }

  void noteBody(const Body& body) {
    if (std::isfinite(body.maxAngularSpeed))
      notes_.push_back("a maximum angular speed of " + say(body.maxAngularSpeed) +
                       " rad/s is not applied: MuJoCo has no angular speed cap");
    if (body.autoDisable.on)
      notes_.push_back("auto-disable is not applied: MuJoCo 2.2 has no sleeping, every body is stepped");
    if (!body.enabled)
      notes_.push_back("bodies asleep in the world are awake: MuJoCo 2.2 has no sleeping");
    if (body.kinematic)
      notes_.push_back("kinematic bodies are MuJoCo mocap bodies, moved by the adapter along their velocity after "
                       "each step: MuJoCo's contacts see them at rest, so they push by overlap only");
    if (!body.gravity)
      notes_.push_back("gravity off on a body: MuJoCo 2.2 has no such switch, so a force of -m g is applied at its "
                       "centre of mass every step");
  }

  void writeContacts() {
    std::ostringstream c;
    for (const world::PairSurface& pair : w_.pairSurfaces) {
      if (pair.surface == w_.defaultSurface || !geomAlive(pair.geom1) || !geomAlive(pair.geom2) ||
          !w_.mayTouch(pair.geom1, pair.geom2))
        continue;
      const ContactParams p = contactOf(w_.surfaces[static_cast<size_t>(pair.surface)], r_.setting,
                                        w_.settings.step, losses_);
      c << "    <pair geom1=\"" << geomName(pair.geom1) << "\" geom2=\"" << geomName(pair.geom2) << "\" condim=\""
        << p.condim << "\" friction=\"" << pairFriction(p.mu) << "\""
        << (p.solref.empty() ? "" : " solref=\"" + p.solref + "\"")
        << (p.solimp.empty() ? "" : " solimp=\"" + p.solimp + "\"") << "/>\n";
    }
    // ODE never lets joined bodies touch; MuJoCo skips a parent and its
    // child itself, and these are the joined bodies that are not.
    std::set<std::pair<int, int>> excluded;
    for (const int j : r_.layout.loops) {
      const Joint& joint = w_.joints[static_cast<size_t>(j)];
      if (joint.body1 >= 0 && joint.body2 >= 0)
        excluded.insert({std::min(joint.body1, joint.body2), std::max(joint.body1, joint.body2)});
    }
    for (const auto& [a, b] : excluded)
      c << "    <exclude body1=\"" << bodyName(a) << "\" body2=\"" << bodyName(b) << "\"/>\n";
    if (!c.str().empty()) s_ << "  <contact>\n" << c.str() << "  </contact>\n";
  }

  // A body that MuJoCo moves: not the world, not a mocap body.
  bool moves(int body) const {
    return body >= 0 && r_.layout.bodies[static_cast<size_t>(body)].kind != Mount::Kind::Mocap;
  }

  void writeLoops() {
    std::ostringstream e;
    const std::string soft = best_ ? " solref=\"" + stiff_ + "\" solimp=\"" + BEST_SOLIMP + "\"" : "";
    for (const int j : r_.layout.loops) {
      const Joint& joint = w_.joints[static_cast<size_t>(j)];
      const JointFrames& frames = r_.frames[static_cast<size_t>(j)];
      if (!moves(joint.body1) && !moves(joint.body2)) {
        notes_.push_back("a joint between two bodies that MuJoCo does not move (the world or kinematic bodies) is "
                         "left out");
        continue;
      }
      if (joint.kind == JointKind::Slider)
        throw EngineError("a slider joint that closes a loop of joints (joint " + std::to_string(j) +
                          "): MuJoCo holds joints in a tree, and version 2.2 has no equality constraint for a slider");
      // The constraint's first body is a body (the anchor is in its frame).
      const bool swap = joint.body1 < 0;
      const int first = swap ? joint.body2 : joint.body1;
      const int second = swap ? joint.body1 : joint.body2;
      const Pose& firstPose = swap ? frames.body2 : frames.body1;
      const std::string bodies = " body1=\"" + bodyName(first) + "\"" +
                                 (second >= 0 ? " body2=\"" + bodyName(second) + "\"" : std::string());
      const Vec3 anchor = pointIn(firstPose, joint.anchor);
      const Vec3 axis = rotate(conj(firstPose.orientation), scale(joint.axis, 1.0 / norm(joint.axis)));
      switch (joint.kind) {
        case JointKind::Ball:
          e << "    <connect" << bodies << " anchor=\"" << vec(anchor) << "\"" << soft << "/>\n";
          break;
        case JointKind::Hinge:
          e << "    <connect" << bodies << " anchor=\"" << vec(anchor) << "\"" << soft << "/>\n"
            << "    <connect" << bodies << " anchor=\"" << vec(add(anchor, scale(axis, HINGE_SPAN))) << "\"" << soft
            << "/>\n";
          if (hasStops(joint))
            notes_.push_back("the stops of a hinge that closes a loop of joints are not applied: it is two MuJoCo "
                             "equality constraints, which have no limits");
          break;
        case JointKind::Fixed:
          e << "    <weld" << bodies << soft << "/>\n";  // held at the model's reference, the joint's
          break;
        case JointKind::Slider:
          break;
      }
      noteJointSoftness(joint);
      notes_.push_back(std::string("a ") + world::jointName(joint.kind) +
                       " joint that closes a loop of joints (MuJoCo holds joints in a tree) is a soft equality "
                       "constraint (" + (joint.kind == JointKind::Hinge ? "two connects along its axis"
                                                                         : joint.kind == JointKind::Ball ? "connect" : "weld") +
                       ", solref " + (best_ ? stiff_ : "0.02 1") + "), which may come apart slightly, as ODE's do");
    }
    if (!e.str().empty()) s_ << "  <equality>\n" << e.str() << "  </equality>\n";
  }

  void noteSettings() {
    const world::Settings& s = w_.settings;
    notes_.push_back("the world's ERP " + say(s.erp) + " and CFM " + say(s.cfm) +
                     " have no MuJoCo equivalent: contacts and joint stops are softened by MuJoCo's solref and solimp "
                     "instead (" + (best_ ? "a time constant of 2 steps" : "MuJoCo's own, solref 0.02 1") + ")");
    notes_.push_back(std::string("ODE's solver settings (") + (s.quickStep ? "QuickStep, " : "dWorldStep, ") +
                     std::to_string(s.iterations) + " iterations) have no MuJoCo equivalent: its Newton solver " +
                     "iterates to its tolerance (1e-8, at most 100 iterations)");
    if (std::isfinite(s.contactMaxCorrectingVelocity))
      notes_.push_back("the contact's maximum correcting velocity " + say(s.contactMaxCorrectingVelocity) +
                       " m/s is not applied: MuJoCo has no such cap");
    if (s.contactSurfaceLayer > 0)
      notes_.push_back("the contact surface layer " + say(s.contactSurfaceLayer) +
                       " m is not applied: MuJoCo's contacts push back from the first overlap");
  }

  const ModelRequest& r_;
  const World& w_;
  const bool best_;
  std::string stiff_;  // Best's solref
  std::ostringstream s_;
  std::vector<std::string> notes_;
  SurfaceLosses losses_;
  ModelText text_;
};

}  // namespace

std::string bodyName(int body) { return "b" + std::to_string(body); }
std::string geomName(int geom) { return "g" + std::to_string(geom); }

ModelText writeModel(const ModelRequest& request) { return Writer(request).write(); }

void initialSizes(const World& world, const Layout& layout, int& nconmax, int& njmax) {
  int bodyGeoms = 0;
  for (const Geom& geom : world.geoms)
    if (geom.body >= 0 && !world.bodies[static_cast<size_t>(geom.body)].removed) ++bodyGeoms;
  nconmax = 100 + 2 * bodyGeoms;
  // MuJoCo 2.2 sizes some of its data as njmax^2 (12 bytes each): room is
  // made as it is needed rather than up front. A contact takes up to 4 rows (a pyramidal cone of dimension 3), a loop
  // constraint up to 6, a stop 1.
  njmax = 4 * nconmax + 6 * static_cast<int>(layout.loops.size()) + 2 * static_cast<int>(world.joints.size());
}

}  // namespace odelab::engines::mujoco
