// The MuJoCo adapter (Debian's MuJoCo 2.2.2): a world description becomes
// MJCF (MujocoModel.cpp), loaded from memory; MuJoCo steps it; the bodies'
// states are read from its forward kinematics (MujocoState.cpp). MuJoCo 2.2
// cannot change a compiled model, so every edit that changes the model (a
// body added or removed, new surfaces or settings, a buffer grown) writes
// and loads the model again and carries every body's state over.
#include <mujoco/mujoco.h>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <string>

#include "Adapters.h"
#include "MujocoModel.h"
#include "MujocoState.h"

namespace odelab::engines {

namespace {

using namespace mujoco;
using world::BodyState;
using world::EngineError;
using world::EngineSetting;
using world::World;

// MuJoCo's own handlers write MUJOCO_LOG.TXT in the working folder and its
// error handler ends the process. Warnings are read from mjData's counters
// after each step instead; an error becomes an EngineError.
void onMujocoWarning(const char*) {}
[[noreturn]] void onMujocoError(const char* message) { throw EngineError(std::string("MuJoCo: ") + message); }

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;

// MJCF text through a virtual file (mjVFS is about 2 MB: on the heap), so
// that no file is left behind. `warning`: what the compiler said of a model
// it built.
ModelPtr loadXml(const std::string& xml, std::string& error) {
  static const char FILE_NAME[] = "world.xml";
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), FILE_NAME, static_cast<int>(xml.size())) != 0)
    throw EngineError("MuJoCo: cannot make the virtual model file");
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), FILE_NAME)], xml.data(), xml.size());
  char text[1000] = "";
  ModelPtr model(mj_loadXML(FILE_NAME, vfs.get(), text, sizeof text));
  mj_deleteVFS(vfs.get());
  error = text;
  return model;
}

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

Pose poseOf(const BodyState& s) { return {s.position, s.orientation}; }
BodyState described(const world::Body& b) {
  return {b.position, b.orientation, b.linearVelocity, b.angularVelocity, true};
}

// What a body was before the model is rebuilt: its joint coordinates (copied
// as they are where it sits on the same joint) and its world state.
struct Carried {
  bool present = false;
  Mount mount;
  Coordinates coordinates;
  BodyState state;
};

class MujocoEngine final : public world::Engine {
 public:
  explicit MujocoEngine(EngineSetting setting) : setting_(setting) {
    mju_user_warning = onMujocoWarning;
    mju_user_error = onMujocoError;
  }

  void build(const World& world) override {
    world_ = world;
    references_.clear();
    frames_.clear();
    for (const world::Body& body : world_.bodies) references_.push_back({body.position, body.orientation});
    std::vector<Carried> none(world_.bodies.size());
    for (size_t j = 0; j < world_.joints.size(); ++j) frames_.push_back(framesOf(world_.joints[j], none));
    nconmax_ = njmax_ = 0;
    reload(none);
  }

  void add(const World& world, int firstBody, int, int firstJoint) override {
    std::vector<Carried> carried = carry();
    const std::vector<world::Body> before = world_.bodies;
    world_ = world;
    for (size_t i = 0; i < before.size() && i < world_.bodies.size(); ++i)
      world_.bodies[i].removed = world_.bodies[i].removed || before[i].removed;
    carried.resize(world_.bodies.size());
    for (size_t i = static_cast<size_t>(firstBody); i < world_.bodies.size(); ++i)
      references_.push_back({world_.bodies[i].position, world_.bodies[i].orientation});
    for (size_t j = static_cast<size_t>(firstJoint); j < world_.joints.size(); ++j)
      frames_.push_back(framesOf(world_.joints[j], carried));
    note(static_cast<size_t>(firstBody) < world_.bodies.size()
             ? "bodies added while running: the model is rebuilt and the state carried over"
             : "static geoms added while running: the model is rebuilt and the state carried over");
    reload(carried);
  }

  void remove(int body) override {
    if (!alive(body)) return;
    std::vector<Carried> carried = carry();
    world_.bodies[static_cast<size_t>(body)].removed = true;
    note("bodies removed while running: the model is rebuilt without them and the state carried over");
    reload(carried);
  }

  void setState(int body, const BodyState& state) override {
    if (alive(body)) pending_[body] = state;
  }

  void applyForce(int body, const Vec3& force, const Vec3& torque) override {
    if (!alive(body)) return;
    Vec3& f = forces_[body].first;
    Vec3& t = forces_[body].second;
    f = mujoco::add(f, force);
    t = mujoco::add(t, torque);
  }

  void changeSettings(const World& world) override {
    std::vector<Carried> carried = carry();
    world_.settings = world.settings;
    world_.surfaces = world.surfaces;
    world_.defaultSurface = world.defaultSurface;
    world_.pairSurfaces = world.pairSurfaces;
    reload(carried);
  }

  void step() override {
    applyPending();
    for (;;) {
      const Snapshot before = snapshot();
      pushForces();
      const auto wall = std::chrono::steady_clock::now();
      const double cpu = cpuSeconds();
      mj_step(model_.get(), data_.get());
      wallSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
      cpuSeconds_ += cpuSeconds() - cpu;
      if (!full()) break;
      // MuJoCo 2.2's contact and constraint buffers are fixed when its data
      // is made and it drops what does not fit: the step is taken again
      // with twice the room.
      nconmax_ *= 2;
      njmax_ *= 2;
      loadModel();
      restore(before);
    }
    checkNumbers();
    if (data_->warning[mjWARN_INERTIA].number > 0)
      note(std::string("MuJoCo warned: ") + mju_warningText(mjWARN_INERTIA, data_->warning[mjWARN_INERTIA].lastinfo));
    moveKinematicBodies();
    forces_.clear();
    fresh_ = false;
  }

  BodyState state(int body) const override {
    if (!alive(body)) return last_.count(body) ? last_.at(body) : BodyState{};
    const_cast<MujocoEngine*>(this)->applyPending();
    if (!fresh_) {
      refreshKinematics(model_.get(), data_.get());
      fresh_ = true;
    }
    const int id = mjBody_[static_cast<size_t>(body)];
    BodyState s;
    if (layout_.bodies[static_cast<size_t>(body)].kind == Mount::Kind::Mocap) {
      const int mocap = model_->body_mocapid[id];
      s.position = {data_->mocap_pos[3 * mocap], data_->mocap_pos[3 * mocap + 1], data_->mocap_pos[3 * mocap + 2]};
      s.orientation = {data_->mocap_quat[4 * mocap], data_->mocap_quat[4 * mocap + 1],
                       data_->mocap_quat[4 * mocap + 2], data_->mocap_quat[4 * mocap + 3]};
      s.linearVelocity = kinematic_.at(body).first;
      s.angularVelocity = kinematic_.at(body).second;
    } else {
      s = readBody(model_.get(), data_.get(), id);
    }
    last_[body] = s;
    return s;
  }

  int contactCount() const override { return data_ ? data_->ncon : -1; }
  const std::vector<std::string>& translationNotes() const override { return notes_; }
  double engineWallSeconds() const override { return wallSeconds_; }
  double engineCpuSeconds() const override { return cpuSeconds_; }

 private:
  // The state before a step, to take it again in a rebuilt model of the same layout.
  struct Snapshot {
    double time;
    std::vector<mjtNum> qpos, qvel, act, warmstart, mocapPos, mocapQuat;
  };

  bool alive(int body) const {
    return body >= 0 && static_cast<size_t>(body) < world_.bodies.size() &&
           !world_.bodies[static_cast<size_t>(body)].removed;
  }

  void note(const std::string& text) {
    if (std::find(notes_.begin(), notes_.end(), text) == notes_.end()) notes_.push_back(text);
  }

  // A joint's reference: its bodies' poses now (the engine's for a body it
  // holds, the description's for one just described).
  JointFrames framesOf(const world::Joint& joint, const std::vector<Carried>& carried) const {
    auto poseNow = [&](int body) -> Pose {
      if (body < 0) return {};
      const size_t i = static_cast<size_t>(body);
      if (i < carried.size() && carried[i].present) return poseOf(carried[i].state);
      return {world_.bodies[i].position, world_.bodies[i].orientation};
    };
    return {poseNow(joint.body1), poseNow(joint.body2)};
  }

  std::vector<Carried> carry() {
    applyPending();
    std::vector<Carried> carried(world_.bodies.size());
    for (size_t i = 0; i < world_.bodies.size(); ++i) {
      if (!alive(static_cast<int>(i)) || i >= mjBody_.size() || mjBody_[i] < 0) continue;
      carried[i].present = true;
      carried[i].mount = layout_.bodies[i];
      carried[i].state = state(static_cast<int>(i));
      carried[i].coordinates = coordinatesOf(model_.get(), data_.get(), mjBody_[i]);
    }
    return carried;
  }

  // A new model from world_, with every body's state carried over (or, for
  // a body not yet held, its described state).
  void reload(const std::vector<Carried>& carried) {
    const double time = data_ ? data_->time : world_.time;
    layout_ = planLayout(world_, references_, frames_);
    int nconmax = 0, njmax = 0;
    initialSizes(world_, layout_, nconmax, njmax);
    nconmax_ = std::max(nconmax_, nconmax);
    njmax_ = std::max(njmax_, njmax);
    loadModel();
    data_->time = time;
    std::map<int, BodyState> desired;
    for (const int body : layout_.order) {
      const size_t i = static_cast<size_t>(body);
      const Carried* c = i < carried.size() && carried[i].present ? &carried[i] : nullptr;
      const Mount& now = layout_.bodies[i];
      if (c && c->mount.kind == now.kind && c->mount.parent == now.parent && c->mount.joint == now.joint &&
          now.kind != Mount::Kind::Mocap) {
        setCoordinates(model_.get(), data_.get(), mjBody_[i], c->coordinates);  // exactly as it was
      } else {
        desired[body] = c ? c->state : described(world_.bodies[i]);
      }
    }
    writeStates(desired);
    mj_forward(model_.get(), data_.get());
    fresh_ = true;
  }

  // Writes and loads the model of layout_ and world_; fresh data.
  void loadModel() {
    for (bool balance : {false, true}) {
      ModelRequest request{world_, layout_, frames_, setting_, nconmax_, njmax_};
      ModelText text = writeModel(request);
      if (balance) text.xml.replace(text.xml.find("<compiler "), 10, "<compiler balanceinertia=\"true\" ");
      std::string error;
      ModelPtr model = loadXml(text.xml, error);
      if (!model && !balance && error.find("A + B >= C") != std::string::npos) continue;
      if (!model && error.find("could not create mjData") != std::string::npos)
        throw EngineError("MuJoCo 2.2 could not make room for " + std::to_string(nconmax_) + " contacts and " +
                          std::to_string(njmax_) + " constraint rows (some of its data grows as the square of the "
                          "rows): too many bodies in contact for it");
      if (!model) throw EngineError("MuJoCo rejected the model written from the world: " + error);
      for (const std::string& n : text.notes) note(n);
      if (balance)
        note("a body's inertia breaks the triangle inequality MuJoCo demands (A + B >= C): MuJoCo's balanceinertia "
             "evened it");
      if (!error.empty()) note("MuJoCo's compiler warned: " + error);
      data_.reset();
      model_ = std::move(model);
      data_.reset(mj_makeData(model_.get()));
      if (!data_) throw EngineError("MuJoCo could not make its data for the model");
      break;
    }
    mjBody_.assign(world_.bodies.size(), -1);
    for (const int body : layout_.order)
      mjBody_[static_cast<size_t>(body)] = mj_name2id(model_.get(), mjOBJ_BODY, bodyName(body).c_str());
  }

  // World states into MuJoCo's coordinates, parents before children (a
  // child's coordinates are relative to its parent as MuJoCo holds it).
  void writeStates(const std::map<int, BodyState>& desired) {
    if (desired.empty()) return;
    int deepest = 0;
    for (const auto& entry : desired) deepest = std::max(deepest, layout_.bodies[static_cast<size_t>(entry.first)].depth);
    for (int depth = 0; depth <= deepest; ++depth) {
      refreshKinematics(model_.get(), data_.get());
      for (const auto& [body, s] : desired) {
        const Mount& mount = layout_.bodies[static_cast<size_t>(body)];
        if (mount.depth != depth) continue;
        const int id = mjBody_[static_cast<size_t>(body)];
        if (mount.kind == Mount::Kind::Mocap) {
          const int mocap = model_->body_mocapid[id];
          const Quat q = normalized(s.orientation);
          for (int k = 0; k < 3; ++k) data_->mocap_pos[3 * mocap + k] = s.position[static_cast<size_t>(k)];
          for (int k = 0; k < 4; ++k) data_->mocap_quat[4 * mocap + k] = q[static_cast<size_t>(k)];
          kinematic_[body] = {s.linearVelocity, s.angularVelocity};
        } else if (mount.kind == Mount::Kind::Free) {
          writeFreeBody(model_.get(), data_.get(), id, s);
        } else {
          const int parent = mount.parent < 0 ? 0 : mjBody_[static_cast<size_t>(mount.parent)];
          writeJointCoordinates(model_.get(), data_.get(), mount, world_.joints[static_cast<size_t>(mount.joint)].kind,
                                id, parent, s);
        }
      }
    }
    refreshKinematics(model_.get(), data_.get());
    fresh_ = true;
  }

  // The states the scene set since the last step, all at once (a parent's
  // first: its children hang from it).
  void applyPending() {
    if (pending_.empty()) return;
    const std::map<int, BodyState> desired = std::move(pending_);
    pending_.clear();
    writeStates(desired);
    for (const auto& [body, s] : desired) {
      const Mount& mount = layout_.bodies[static_cast<size_t>(body)];
      if (mount.kind == Mount::Kind::Joint) {
        const BodyState got = readBody(model_.get(), data_.get(), mjBody_[static_cast<size_t>(body)]);
        if (norm(sub(got.position, s.position)) > 1e-9 * (1.0 + norm(s.position)) ||
            norm(sub(got.linearVelocity, s.linearVelocity)) > 1e-9 * (1.0 + norm(s.linearVelocity)))
          note("a state set on a body held by a MuJoCo joint keeps only what its joint allows (its angle or "
               "position and their rate relative to its parent)");
      }
      for (const int child : layout_.children[static_cast<size_t>(body)])
        if (!desired.count(child))
          note("a state set on a body moves the bodies jointed to it (MuJoCo holds them relative to it)");
    }
  }

  Snapshot snapshot() const {
    const mjModel* m = model_.get();
    const mjData* d = data_.get();
    return {d->time,
            {d->qpos, d->qpos + m->nq},
            {d->qvel, d->qvel + m->nv},
            {d->act, d->act + m->na},
            {d->qacc_warmstart, d->qacc_warmstart + m->nv},
            {d->mocap_pos, d->mocap_pos + 3 * m->nmocap},
            {d->mocap_quat, d->mocap_quat + 4 * m->nmocap}};
  }
  void restore(const Snapshot& s) {
    mjData* d = data_.get();
    d->time = s.time;
    std::copy(s.qpos.begin(), s.qpos.end(), d->qpos);
    std::copy(s.qvel.begin(), s.qvel.end(), d->qvel);
    std::copy(s.act.begin(), s.act.end(), d->act);
    std::copy(s.warmstart.begin(), s.warmstart.end(), d->qacc_warmstart);
    std::copy(s.mocapPos.begin(), s.mocapPos.end(), d->mocap_pos);
    std::copy(s.mocapQuat.begin(), s.mocapQuat.end(), d->mocap_quat);
  }

  bool full() const {
    return data_->warning[mjWARN_CONTACTFULL].number > 0 || data_->warning[mjWARN_CNSTRFULL].number > 0;
  }

  // The forces for this step, and gravity taken off the bodies that have it off.
  void pushForces() {
    mju_zero(data_->xfrc_applied, 6 * model_->nbody);
    for (const int body : layout_.order) {
      const Mount& mount = layout_.bodies[static_cast<size_t>(body)];
      if (mount.kind == Mount::Kind::Mocap) continue;
      mjtNum* f = data_->xfrc_applied + 6 * mjBody_[static_cast<size_t>(body)];
      const world::Body& b = world_.bodies[static_cast<size_t>(body)];
      if (!b.gravity)
        for (int k = 0; k < 3; ++k) f[k] -= b.mass * world_.settings.gravity[static_cast<size_t>(k)];
      const auto applied = forces_.find(body);
      if (applied == forces_.end()) continue;
      for (int k = 0; k < 3; ++k) {
        f[k] += applied->second.first[static_cast<size_t>(k)];
        f[3 + k] += applied->second.second[static_cast<size_t>(k)];
      }
    }
  }

  // MuJoCo answers a NaN, an infinity or a huge number in its state by
  // resetting the simulation and going on: a run measured after that would
  // be a lie, so it ends here.
  void checkNumbers() const {
    static const std::pair<int, const char*> BAD[] = {
        {mjWARN_BADQPOS, "position"}, {mjWARN_BADQVEL, "velocity"}, {mjWARN_BADQACC, "acceleration"}};
    for (const auto& [warning, what] : BAD)
      if (data_->warning[warning].number > 0)
        throw EngineError(std::string("MuJoCo found a bad ") + what + " (NaN, infinite or huge) at t = " +
                          std::to_string(data_->time) + " s and reset its simulation");
  }

  // Mocap bodies move only as the adapter moves them: along their velocity.
  void moveKinematicBodies() {
    const double h = world_.settings.step;
    for (const auto& [body, velocity] : kinematic_) {
      if (!alive(body)) continue;
      const int mocap = model_->body_mocapid[mjBody_[static_cast<size_t>(body)]];
      for (int k = 0; k < 3; ++k) data_->mocap_pos[3 * mocap + k] += h * velocity.first[static_cast<size_t>(k)];
      const double speed = norm(velocity.second);
      if (speed == 0.0) continue;
      const Vec3 axis = scale(velocity.second, std::sin(0.5 * speed * h) / speed);
      const Quat turn{std::cos(0.5 * speed * h), axis[0], axis[1], axis[2]};
      mjtNum* q = data_->mocap_quat + 4 * mocap;
      const Quat turned = normalized(mul(turn, {q[0], q[1], q[2], q[3]}));
      for (int k = 0; k < 4; ++k) q[k] = turned[static_cast<size_t>(k)];
    }
  }

  const EngineSetting setting_;
  World world_;
  std::vector<Pose> references_;    // per body: its pose when first described
  std::vector<JointFrames> frames_;  // per joint: its reference
  Layout layout_;
  ModelPtr model_;
  DataPtr data_;
  int nconmax_ = 0, njmax_ = 0;
  std::vector<int> mjBody_;  // per body: MuJoCo's body id, -1 when removed
  std::map<int, std::pair<Vec3, Vec3>> kinematic_;  // mocap bodies' velocities (linear, angular)
  std::map<int, std::pair<Vec3, Vec3>> forces_;     // force and torque for the next step
  std::map<int, BodyState> pending_;                // states set since the last step
  mutable std::map<int, BodyState> last_;           // every body's last state read (a removed one's stays)
  mutable bool fresh_ = false;
  std::vector<std::string> notes_;
  double wallSeconds_ = 0.0, cpuSeconds_ = 0.0;
};

std::string versionText() {  // mj_version(): 222 for 2.2.2
  const int v = mj_version();
  return std::to_string(v / 100) + "." + std::to_string(v / 10 % 10) + "." + std::to_string(v % 10);
}

}  // namespace

world::EngineInfo mujocoInfo() {
  world::EngineInfo info;
  info.name = "mujoco";
  info.version = versionText();
  info.available = true;
  info.precision = "double";
  info.bestSettings =
      "contacts at the stiffest time constant MuJoCo accepts (solref 2 steps, damping ratio 1) with solimp "
      "0.99 0.999 0.001, the same for joint stops and loop-closing joints, and elliptic friction cones; a bouncing "
      "surface becomes a spring-damper contact (solref -5000 -b, b from the restitution); the RK4 integrator when "
      "the world has a hinge or slider joint or a bouncing surface (Default: MuJoCo's own contact solref 0.02 1, "
      "pyramidal cones, semi-implicit Euler)";
  return info;
}

std::unique_ptr<world::Engine> makeMujoco(world::EngineSetting setting) {
  return std::make_unique<MujocoEngine>(setting);
}

}  // namespace odelab::engines
