// Havok, Jolt and Rapier run in Node.js, through their npm WebAssembly
// builds: each engine is a child process (peers/wasm/engine_server.js)
// that this adapter speaks to over its pipes in JSON lines
// (doc/engine-protocol.md). The child builds the world from the same world
// JSON every adapter reads, steps it, and answers each step with every
// body's state, which is kept here for state(). Its stderr is the
// program's. If it dies or answers what is not the protocol, the call
// throws world::EngineError naming the engine and how it ended.
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "Adapters.h"
#include "EnginePipe.h"
#include "world/WorldJson.h"

namespace odelab::engines {

namespace {

using nlohmann::json;

struct NodeEngineKind {
  const char* name;
  const char* title;    // in messages
  const char* package;  // under peers/wasm/node_modules
  const char* best;     // what --engine-setting best changes (src/engines/<name>.js says why)
};

const NodeEngineKind KINDS[] = {
    {"havok", "Havok", "@babylonjs/havok",
     "the solver tuned for the world's step (ideal step time h, not 1/60 s), no damping (default angular 0.1), "
     "speed caps raised out of reach (default 200 m/s, 100 rad/s)"},
    {"jolt", "Jolt", "jolt-physics",
     "no damping (default 0.05 linear and angular), 50 velocity and 10 position iterations (default 10 and 2), "
     "restitution from the world's bounce velocity (default: none below 1 m/s), speed caps out of reach "
     "(default 500 m/s, 47 rad/s), swept motion (LinearCast) for every moving body"},
    {"rapier", "Rapier", "@dimforge/rapier3d-compat",
     "50 solver iterations (default 4), continuous collision (CCD) for every moving body, the speed cap "
     "(400 m/s x lengthUnit) out of reach: lengthUnit 1000 with its length tolerances divided by 1000"},
};

const NodeEngineKind* kindOf(const std::string& name) {
  for (const NodeEngineKind& kind : KINDS)
    if (name == kind.name) return &kind;
  return nullptr;
}

// node: $ODELAB_NODE, else what CMake found.
std::string nodeProgram() {
  if (const char* env = std::getenv("ODELAB_NODE"); env && *env) return env;
  const std::string found = ODELAB_NODE_PROGRAM;
  if (found.empty() || found.find("NOTFOUND") != std::string::npos) return "node";
  return found;
}

bool executable(const std::string& program) {
  if (program.find('/') != std::string::npos) return ::access(program.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  return false;
}

std::string serverPath() { return ODELAB_ENGINE_SERVER; }

std::string wasmDirectory() {
  const std::string server = serverPath();
  return server.substr(0, server.find_last_of('/'));
}

// The installed package's version ("" when it is not installed).
std::string packageVersion(const NodeEngineKind& kind) {
  std::ifstream file(wasmDirectory() + "/node_modules/" + kind.package + "/package.json");
  if (!file) return "";
  try {
    const json package = json::parse(file);
    return package.value("version", "?");
  } catch (const json::exception&) {
    return "";
  }
}

const std::string INSTALL = "install Node.js (Debian's nodejs) and run `npm ci` in peers/wasm";

// A state from the server: 14 numbers (null for a number that was not
// finite), the last the enabled flag.
bool readState(const json& value, world::BodyState& state) {
  if (!value.is_array() || value.size() != 14) return false;
  double v[14];
  for (size_t i = 0; i < 14; ++i) {
    if (value[i].is_null()) v[i] = std::numeric_limits<double>::quiet_NaN();
    else if (value[i].is_number()) v[i] = value[i].get<double>();
    else return false;
  }
  state.position = {v[0], v[1], v[2]};
  state.orientation = {v[3], v[4], v[5], v[6]};
  state.linearVelocity = {v[7], v[8], v[9]};
  state.angularVelocity = {v[10], v[11], v[12]};
  state.enabled = v[13] != 0;
  return true;
}

class NodeEngine : public world::Engine {
 public:
  NodeEngine(const NodeEngineKind& kind, world::EngineSetting setting) : name_(kind.title) {
    const std::vector<std::string> argv{nodeProgram(), "--no-concurrent-recompilation", serverPath(), kind.name,
                                        setting == world::EngineSetting::Best ? "best" : "default"};
    try {
      pipe_ = std::make_unique<EnginePipe>(argv);
    } catch (const std::exception& error) {
      throw world::EngineError(name_ + ": " + error.what() + " (" + INSTALL + ")");
    }
  }

  ~NodeEngine() override {
    if (pipe_) pipe_->writeLine(R"({"op":"quit"})");
    // EnginePipe's destructor closes the pipe and waits for the child.
  }

  void build(const world::World& world) override {
    json message = worldMessage("build", world);
    takeStates(request(message));
  }

  void add(const world::World& world, int firstBody, int firstGeom, int firstJoint) override {
    json message = worldMessage("add", world);
    message["first_body"] = firstBody;
    message["first_geom"] = firstGeom;
    message["first_joint"] = firstJoint;
    takeStates(request(message));
  }

  void remove(int body) override { send({{"op", "remove"}, {"body", body}}); }

  void setState(int body, const world::BodyState& s) override {
    send({{"op", "set_state"},
          {"body", body},
          {"state",
           {s.position[0], s.position[1], s.position[2], s.orientation[0], s.orientation[1], s.orientation[2],
            s.orientation[3], s.linearVelocity[0], s.linearVelocity[1], s.linearVelocity[2], s.angularVelocity[0],
            s.angularVelocity[1], s.angularVelocity[2], s.enabled ? 1 : 0}}});
    // state() reads what was set until the next step answers.
    if (body >= 0 && static_cast<size_t>(body) < states_.size()) states_[body] = s;
  }

  void applyForce(int body, const world::Vec3& force, const world::Vec3& torque) override {
    send({{"op", "force"},
          {"body", body},
          {"force", {force[0], force[1], force[2]}},
          {"torque", {torque[0], torque[1], torque[2]}}});
  }

  void changeSettings(const world::World& world) override { send(worldMessage("settings", world)); }

  void step() override {
    const json reply = request({{"op", "step"}, {"count", 1}});
    takeStates(reply);
    const auto number = [&](const char* key, double fallback) {
      const auto it = reply.find(key);
      return it != reply.end() && it->is_number() ? it->get<double>() : fallback;
    };
    contacts_ = static_cast<int>(number("contacts", -1));
    wall_ = number("engine_wall_s", wall_);
    cpu_ = number("engine_cpu_s", cpu_);
  }

  world::BodyState state(int body) const override {
    if (body < 0 || static_cast<size_t>(body) >= states_.size())
      throw world::EngineError(name_ + ": no body " + std::to_string(body));
    return states_[body];
  }

  int contactCount() const override { return contacts_; }
  const std::vector<std::string>& translationNotes() const override { return notes_; }
  double engineWallSeconds() const override { return wall_; }
  double engineCpuSeconds() const override { return cpu_; }

 private:
  std::string name_;  // "Jolt"
  std::unique_ptr<EnginePipe> pipe_;
  std::vector<world::BodyState> states_;
  std::vector<std::string> notes_;
  int contacts_ = -1;
  double wall_ = 0, cpu_ = 0;

  // The world as JSON with every body in it, removed ones named apart:
  // worldToJson leaves removed bodies out and renumbers the rest, and the
  // server must keep the program's indices.
  static json worldMessage(const char* op, const world::World& world) {
    world::World copy = world;
    json removed = json::array();
    for (size_t i = 0; i < copy.bodies.size(); ++i)
      if (copy.bodies[i].removed) {
        removed.push_back(i);
        copy.bodies[i].removed = false;
      }
    return {{"op", op}, {"world", json::parse(world::worldToJson(copy))}, {"removed", removed}};
  }

  [[noreturn]] void died(const std::string& doing) {
    throw world::EngineError(name_ + "'s Node.js engine server ended while " + doing + " (" + pipe_->endedHow() +
                             "; its messages are above on stderr)");
  }

  void send(const json& message) {
    if (!pipe_->writeLine(message.dump())) died("taking a message");
  }

  json request(const json& message) {
    send(message);
    std::string line;
    if (!pipe_->readLine(line)) died("answering '" + message.value("op", std::string()) + "'");
    json reply;
    try {
      reply = json::parse(line);
    } catch (const json::exception&) {
      throw world::EngineError(name_ + "'s Node.js engine server answered what is not JSON: " + line.substr(0, 200));
    }
    if (!reply.is_object())
      throw world::EngineError(name_ + "'s Node.js engine server answered what is not a reply: " + line.substr(0, 200));
    if (const auto error = reply.find("error"); error != reply.end())
      throw world::EngineError(name_ + ": " + (error->is_string() ? error->get<std::string>() : error->dump()));
    if (const auto notes = reply.find("notes"); notes != reply.end() && notes->is_array())
      for (const json& note : *notes)
        if (note.is_string()) notes_.push_back(note.get<std::string>());
    return reply;
  }

  void takeStates(const json& reply) {
    const auto states = reply.find("states");
    if (states == reply.end() || !states->is_array())
      throw world::EngineError(name_ + "'s Node.js engine server's reply has no states");
    states_.resize(states->size());
    for (size_t i = 0; i < states->size(); ++i) {
      if ((*states)[i].is_null()) continue;  // a removed body keeps its last state
      if (!readState((*states)[i], states_[i]))
        throw world::EngineError(name_ + "'s Node.js engine server sent a state that is not 14 numbers (body " +
                                 std::to_string(i) + ")");
    }
  }
};

}  // namespace

std::vector<std::string> nodeEngineNames() {
  std::vector<std::string> names;
  for (const NodeEngineKind& kind : KINDS) names.push_back(kind.name);
  return names;
}

world::EngineInfo nodeEngineInfo(const std::string& name) {
  world::EngineInfo info;
  info.name = name;
  info.precision = "float32";
  const NodeEngineKind* kind = kindOf(name);
  if (!kind) {
    info.missing = "not one of havok, jolt, rapier";
    return info;
  }
  info.bestSettings = kind->best;
  const std::string node = nodeProgram();
  if (!executable(node)) {
    info.missing = "Node.js (" + node + ") not found: " + INSTALL;
    return info;
  }
  if (::access(serverPath().c_str(), R_OK) != 0) {
    info.missing = serverPath() + " not found";
    return info;
  }
  info.version = packageVersion(*kind);
  if (info.version.empty()) {
    info.missing = std::string("the npm package ") + kind->package + " is not installed: " + INSTALL;
    return info;
  }
  info.available = true;
  return info;
}

std::unique_ptr<world::Engine> makeNodeEngine(const std::string& name, world::EngineSetting setting) {
  const NodeEngineKind* kind = kindOf(name);
  if (!kind) throw world::EngineError("'" + name + "' is not one of havok, jolt, rapier");
  return std::make_unique<NodeEngine>(*kind, setting);
}

}  // namespace odelab::engines
