// MJCF in (WorldFromMjcf.h): MuJoCo parses and compiles the file (defaults,
// classes, degrees, inertia from geoms), mj_forward places every body at
// qpos0, and this file reads the compiled mjModel and mjData into a World.
// MuJoCo's z-up frame is turned to this format's y-up one: (x, y, z) ->
// (x, z, -y), a rotation of -90 degrees about x: exact for every vector,
// orientations turned by its quaternion.
#include "WorldFromMjcf.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include "WorldJson.h"

namespace odelab::world {

namespace {

// 0.0 - y, not -y: a 0 stays 0 rather than -0 in the exported file.
Vec3 yUp(const mjtNum* v) { return {v[0], v[2], 0.0 - v[1]}; }

// The rotation yUp applies, as a quaternion: about x by -90 degrees.
Quat yUpQuat(const mjtNum* q) {
  const mjtNum half = std::sqrt(0.5);
  const mjtNum turn[4] = {half, -half, 0, 0};
  mjtNum out[4];
  mju_mulQuat(out, turn, q);
  return {out[0], out[1], out[2], out[3]};
}

std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

class Translation {
 public:
  Translation(const mjModel* m, const mjData* d, std::string path) : m_(m), d_(d), path_(std::move(path)) {}

  World run() {
    refuseWholeModelParts();
    settings();
    bodies();
    geoms();
    joints();
    surfaces();
    standingNotes();
    return std::move(world_);
  }

 private:
  std::string name(int type, int id, const char* kind) const {
    const char* own = mj_id2name(m_, type, id);
    return own && *own ? std::string(kind) + " '" + own + "'" : std::string(kind) + " " + std::to_string(id);
  }

  [[noreturn]] void refuse(const std::string& what) const {
    throw WorldFileError(path_ + ": MJCF: " + what + " (doc/world-format.md, \"MJCF\", says what is read)");
  }

  void note(const std::string& what) { world_.notes.push_back(what); }

  // Parts that constrain or drive the bodies: running without them would be
  // another mechanism, so they are refused rather than noted.
  void refuseWholeModelParts() const {
    if (m_->ntendon > 0) refuse(std::to_string(m_->ntendon) + " tendon(s): this format has no tendons");
    if (m_->neq > 0) refuse(std::to_string(m_->neq) + " equality constraint(s): this format has none");
    if (m_->npair > 0 || m_->nexclude > 0)
      refuse("<contact> pair or exclude elements: this format filters contacts by contype/conaffinity bits only");
    if (m_->opt.density != 0 || m_->opt.viscosity != 0 || m_->opt.wind[0] != 0 || m_->opt.wind[1] != 0 ||
        m_->opt.wind[2] != 0)
      refuse("<option> density, viscosity or wind: this format has no medium forces");
  }

  void settings() {
    world_.scene = "mjcf";
    const char* model = m_->names;  // the model's name comes first in MuJoCo's names
    world_.title = model && *model ? model : "MJCF model";
    world_.settings.step = m_->opt.timestep;
    world_.settings.gravity = yUp(m_->opt.gravity);
    mjOption plain;
    mj_defaultOption(&plain);
    const mjOption& o = m_->opt;
    if (o.integrator != plain.integrator || o.solver != plain.solver || o.iterations != plain.iterations ||
        o.tolerance != plain.tolerance || o.cone != plain.cone || o.impratio != plain.impratio ||
        o.jacobian != plain.jacobian || o.noslip_iterations != plain.noslip_iterations)
      note("<option> integrator, solver, iterations, tolerance, cone, impratio, jacobian or noslip not carried: "
           "the world takes this format's solver settings (ODE's QuickStep, 20 iterations)");
    if (o.disableflags != 0 || o.enableflags != 0)
      note("<option><flag> settings not carried: every flag is MuJoCo's default here");
    if (m_->nkey > 0) note(std::to_string(m_->nkey) + " keyframe(s) not carried: the bodies start at qpos0");
    if (m_->nu > 0) note(std::to_string(m_->nu) + " actuator(s) not carried: nothing drives the joints");
    if (m_->nsensor > 0) note(std::to_string(m_->nsensor) + " sensor(s) not carried");
  }

  // A body moves when it is not welded to the world (MuJoCo's body_weldid):
  // it has a joint, or hangs without one from a body that has.
  void bodies() {
    index_.assign(static_cast<size_t>(m_->nbody), -1);
    for (int b = 1; b < m_->nbody; ++b) {
      if (m_->body_weldid[b] == 0) continue;
      const double mass = m_->body_mass[b];
      if (!(mass > 0)) refuse(name(mjOBJ_BODY, b, "body") + " moves and has mass " + number(mass) + ": this format needs a mass above 0");
      Body body;
      body.mass = mass;
      // MuJoCo gives the principal moments in the frame body_iquat turns to;
      // the format holds the full tensor in the body's frame: R diag(I) R^T.
      mjtNum r[9];
      mju_quat2Mat(r, m_->body_iquat + 4 * b);
      const mjtNum* moment = m_->body_inertia + 3 * b;
      const auto entry = [&](int i, int j) {
        double sum = 0;
        for (int k = 0; k < 3; ++k) sum += r[3 * i + k] * moment[k] * r[3 * j + k];
        return sum;
      };
      body.inertia = {entry(0, 0), entry(1, 1), entry(2, 2), entry(0, 1), entry(0, 2), entry(1, 2)};
      body.position = yUp(d_->xipos + 3 * b);
      body.orientation = yUpQuat(d_->xquat + 4 * b);
      index_[static_cast<size_t>(b)] = static_cast<int>(world_.bodies.size());
      world_.bodies.push_back(body);
    }
  }

  // Body by body (MuJoCo keeps each body's geoms together, in body order), so
  // that a body's first geom comes in the bodies' order: the exporter numbers
  // bodies as it meets them through their geoms, and keeps MuJoCo's order so.
  void geoms() {
    for (int b = 0; b < m_->nbody; ++b) {
      for (int k = 0; k < m_->body_geomnum[b]; ++k) addGeom(m_->body_geomadr[b] + k);
      const int body = index_[static_cast<size_t>(b)];
      if (body >= 0 && m_->body_geomnum[b] == 0) {
        // The format finds a body through its geoms: a body MuJoCo gives mass
        // by <inertial> alone carries a sphere that touches nothing.
        Geom marker;
        marker.shape = ShapeKind::Sphere;
        marker.size = {1e-3, 0, 0};
        marker.body = body;
        marker.category = 0;
        marker.collide = 0;
        mjGeomOf_.push_back(-1);
        world_.geoms.push_back(marker);
      }
    }
    if (margins_) note("geom margin and gap not carried: contacts start at touching");
    if (higherCondim_) note("condim 4 and 6 (torsional and rolling friction) not carried: contacts have sliding friction only");
  }

  void addGeom(int g) {
    const int mjBody = m_->geom_bodyid[g];
    const int body = index_[static_cast<size_t>(mjBody)];
    const mjtNum* size = m_->geom_size + 3 * g;
    Geom geom;
    geom.body = body;
    switch (m_->geom_type[g]) {
      case mjGEOM_PLANE: geom.shape = ShapeKind::Plane; break;
      case mjGEOM_SPHERE: geom.shape = ShapeKind::Sphere; geom.size = {size[0], 0, 0}; break;
      case mjGEOM_BOX: geom.shape = ShapeKind::Box; geom.size = {2 * size[0], 2 * size[1], 2 * size[2]}; break;
      // MuJoCo's size[1] is the half-length of the cylindrical part, along local z as here.
      case mjGEOM_CAPSULE: geom.shape = ShapeKind::Capsule; geom.size = {size[0], 2 * size[1], 0}; break;
      case mjGEOM_CYLINDER: geom.shape = ShapeKind::Cylinder; geom.size = {size[0], 2 * size[1], 0}; break;
      default: refuse(name(mjOBJ_GEOM, g, "geom") + " is of type " + typeName(m_->geom_type[g]) +
                      ": this format has box, sphere, plane, capsule and cylinder only");
    }
    const mjtNum* xpos = d_->geom_xpos + 3 * g;
    mjtNum xquat[4];
    mju_mat2Quat(xquat, d_->geom_xmat + 9 * g);
    if (geom.shape == ShapeKind::Plane) {
      if (body >= 0) refuse(name(mjOBJ_GEOM, g, "geom") + " is a plane on a moving body: a plane is static here");
      // MuJoCo's plane is its geom frame's z = 0, normal along that z.
      const mjtNum* mat = d_->geom_xmat + 9 * g;
      const mjtNum normal[3] = {mat[2], mat[5], mat[8]};
      const Vec3 n = yUp(normal);
      const Vec3 p = yUp(xpos);
      geom.plane = {n[0], n[1], n[2], n[0] * p[0] + n[1] * p[1] + n[2] * p[2]};
    } else if (body < 0) {
      geom.position = yUp(xpos);
      geom.orientation = yUpQuat(xquat);
    } else {
      // On a body: relative to its centre of mass, in its frame.
      const mjtNum* bodyMat = d_->xmat + 9 * mjBody;
      const mjtNum* com = d_->xipos + 3 * mjBody;
      const mjtNum offset[3] = {xpos[0] - com[0], xpos[1] - com[1], xpos[2] - com[2]};
      mjtNum local[3];
      mju_rotVecMatT(local, offset, bodyMat);
      geom.position = {local[0], local[1], local[2]};
      mjtNum inverse[4], relative[4];
      mju_negQuat(inverse, d_->xquat + 4 * mjBody);
      mju_mulQuat(relative, inverse, xquat);
      geom.orientation = {relative[0], relative[1], relative[2], relative[3]};
    }
    // MuJoCo's contype/conaffinity rule is ODE's category/collide rule.
    geom.category = static_cast<std::uint32_t>(m_->geom_contype[g]);
    geom.collide = static_cast<std::uint32_t>(m_->geom_conaffinity[g]);
    margins_ = margins_ || m_->geom_margin[g] != 0 || m_->geom_gap[g] != 0;
    higherCondim_ = higherCondim_ || m_->geom_condim[g] > 3;
    mjGeomOf_.push_back(g);
    world_.geoms.push_back(geom);
  }

  static const char* typeName(int type) {
    switch (type) {
      case mjGEOM_HFIELD: return "hfield";
      case mjGEOM_ELLIPSOID: return "ellipsoid";
      case mjGEOM_MESH: return "mesh";
      default: return "unknown to this reader";
    }
  }

  void joints() {
    for (int b = 1; b < m_->nbody; ++b) {
      const int self = index_[static_cast<size_t>(b)];
      if (self < 0) continue;
      const int parent = index_[static_cast<size_t>(m_->body_parentid[b])];
      const int count = m_->body_jntnum[b];
      if (count > 1)
        refuse(name(mjOBJ_BODY, b, "body") + " has " + std::to_string(count) +
               " joints: this format joins two bodies with one joint");
      if (count == 0) {
        // Welded to a moving parent (MuJoCo makes them one body): a fixed joint.
        Joint fixed;
        fixed.kind = JointKind::Fixed;
        fixed.body1 = self;
        fixed.body2 = parent;
        world_.joints.push_back(fixed);
        continue;
      }
      const int j = m_->body_jntadr[b];
      refuseDynamics(j);
      const int type = m_->jnt_type[j];
      if (type == mjJNT_FREE) continue;  // a free body: no joint
      Joint joint;
      // The child first: ODE's hinge angle and slider position then grow as
      // MuJoCo's qpos does, so the range maps with qpos0 as ODE's zero.
      joint.body1 = self;
      joint.body2 = parent;
      joint.anchor = yUp(d_->xanchor + 3 * j);
      joint.axis = yUp(d_->xaxis + 3 * j);
      if (type == mjJNT_BALL) {
        joint.kind = JointKind::Ball;
        if (m_->jnt_limited[j]) refuse(name(mjOBJ_JOINT, j, "joint") + " is a ball with a range: this format's ball has no cone limit");
      } else {
        joint.kind = type == mjJNT_HINGE ? JointKind::Hinge : JointKind::Slider;
        if (m_->jnt_limited[j]) {
          const double zero = m_->qpos0[m_->jnt_qposadr[j]];
          joint.lowStop = m_->jnt_range[2 * j] - zero;
          joint.highStop = m_->jnt_range[2 * j + 1] - zero;
        }
      }
      world_.joints.push_back(joint);
    }
  }

  // Damping, armature, friction loss and springs act on every step: a run
  // without them is another mechanism, so the file is refused naming them.
  void refuseDynamics(int j) const {
    if (m_->jnt_stiffness[j] != 0)
      refuse(name(mjOBJ_JOINT, j, "joint") + " has stiffness " + number(m_->jnt_stiffness[j]) + ": this format has no joint springs");
    const int dofs = m_->jnt_type[j] == mjJNT_FREE ? 6 : m_->jnt_type[j] == mjJNT_BALL ? 3 : 1;
    for (int k = 0; k < dofs; ++k) {
      const int dof = m_->jnt_dofadr[j] + k;
      if (m_->dof_damping[dof] != 0)
        refuse(name(mjOBJ_JOINT, j, "joint") + " has damping " + number(m_->dof_damping[dof]) + ": this format has no joint damping");
      if (m_->dof_armature[dof] != 0)
        refuse(name(mjOBJ_JOINT, j, "joint") + " has armature " + number(m_->dof_armature[dof]) + ": this format has no armature");
      if (m_->dof_frictionloss[dof] != 0)
        refuse(name(mjOBJ_JOINT, j, "joint") + " has frictionloss " + number(m_->dof_frictionloss[dof]) + ": this format has no joint friction");
    }
  }

  // MuJoCo's pair friction: the higher-priority geom's, else the larger of
  // the two; condim 1 is frictionless. One surface per value a pair takes,
  // the most used as the default.
  double pairMu(int a, int b) const {
    const int ga = mjGeomOf_[static_cast<size_t>(a)], gb = mjGeomOf_[static_cast<size_t>(b)];
    if (std::max(m_->geom_condim[ga], m_->geom_condim[gb]) == 1) return 0.0;
    const double muA = m_->geom_friction[3 * ga], muB = m_->geom_friction[3 * gb];
    if (m_->geom_priority[ga] != m_->geom_priority[gb]) return m_->geom_priority[ga] > m_->geom_priority[gb] ? muA : muB;
    return std::max(muA, muB);
  }

  void surfaces() {
    std::map<double, int> surfaceOf;
    std::vector<PairSurface> pairs;
    std::vector<int> uses;
    for (int a = 0; a < static_cast<int>(world_.geoms.size()); ++a)
      for (int b = a + 1; b < static_cast<int>(world_.geoms.size()); ++b) {
        if (mjGeomOf_[static_cast<size_t>(a)] < 0 || mjGeomOf_[static_cast<size_t>(b)] < 0 || !world_.mayTouch(a, b)) continue;
        const double mu = pairMu(a, b);
        auto found = surfaceOf.find(mu);
        if (found == surfaceOf.end()) {
          found = surfaceOf.emplace(mu, static_cast<int>(world_.surfaces.size())).first;
          Surface surface;
          surface.mu = mu;
          surface.approx1 = true;  // ODE's mu is then a coefficient, as MuJoCo's is, not a force in newtons
          world_.surfaces.push_back(surface);
          uses.push_back(0);
        }
        ++uses[static_cast<size_t>(found->second)];
        pairs.push_back({a, b, found->second});
      }
    if (world_.surfaces.empty()) {
      Surface surface;
      surface.mu = m_->ngeom > 0 ? m_->geom_friction[0] : 1.0;
      surface.approx1 = true;
      world_.surfaces.push_back(surface);
      uses.push_back(0);
    }
    world_.defaultSurface = static_cast<int>(std::max_element(uses.begin(), uses.end()) - uses.begin());
    for (const PairSurface& pair : pairs)
      if (pair.surface != world_.defaultSurface) world_.pairSurfaces.push_back(pair);
    if (world_.surfaces.size() > 1 || pairs.size() > 0)
      note("friction: each geom's first friction coefficient, a pair taking MuJoCo's rule (the higher priority's, "
           "else the larger); its torsional and rolling coefficients are not carried");
  }

  void standingNotes() {
    note("solref not carried: contacts and limits are ODE's, stiff by the world's ERP and CFM, not MuJoCo's soft springs (so nothing bounces)");
    note("solimp not carried: ODE's contacts have no impedance curve");
  }

  const mjModel* m_;
  const mjData* d_;
  std::string path_;
  World world_;
  std::vector<int> index_;     // per MuJoCo body: its index in world_.bodies, -1 static
  std::vector<int> mjGeomOf_;  // per world geom: its MuJoCo geom, -1 a marker sphere
  bool margins_ = false, higherCondim_ = false;  // noted once, after every geom
};

}  // namespace

World worldFromMjcf(const std::string& path) {
  char error[1024] = "";
  std::unique_ptr<mjModel, void (*)(mjModel*)> model(mj_loadXML(path.c_str(), nullptr, error, sizeof error),
                                                      mj_deleteModel);
  if (!model) throw WorldFileError(path + ": MuJoCo refused it: " + error);
  std::unique_ptr<mjData, void (*)(mjData*)> data(mj_makeData(model.get()), mj_deleteData);
  if (!data) throw WorldFileError(path + ": MuJoCo could not allocate the model's data");
  mj_forward(model.get(), data.get());  // every pose at qpos0
  World world = Translation(model.get(), data.get(), path).run();
  // Through this format's own reader: its ranges and physics checks
  // (positive-definite inertia, unit normals) hold the translation too.
  const std::vector<std::string> notes = world.notes;
  try {
    world = worldFromJson(worldToJson(world));
  } catch (const WorldFileError& error) {
    throw WorldFileError(path + ": MJCF as translated: " + error.what());
  }
  world.notes = notes;
  return world;
}

}  // namespace odelab::world
