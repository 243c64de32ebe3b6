// The protocol's C++ side (doc/engine-protocol.md): each call becomes a
// message; each step's reply holds every body's state, kept here for
// state(). If the other side ends or answers what is not the protocol, the
// call throws world::EngineError naming the engine and how it ended.
#include "ProtocolEngine.h"

#include <nlohmann/json.hpp>

#include <limits>
#include <utility>
#include <vector>

#include "world/WorldJson.h"

namespace odelab::engines {

namespace {

using nlohmann::json;

// The deadlines' parts (doc/engine-protocol.md, "Deadlines"): a build or add
// starts from a minute (Node.js starting and compiling the engine's
// WebAssembly on a loaded machine take seconds), every other message from
// ten seconds; each body, geom or joint it carries or the world holds adds
// a millisecond, and each step asked for ten times that per body on top of
// its own ten milliseconds. The slowest step seen in the lab (its largest
// world, on Havok) is a few milliseconds.
constexpr double BUILD_BASE_SECONDS = 60.0;
constexpr double MESSAGE_BASE_SECONDS = 10.0;
constexpr double SECONDS_PER_PART = 1e-3;
constexpr double SECONDS_PER_STEP = 1e-2;
constexpr double SECONDS_PER_PART_STEP = 1e-2;

std::size_t partsOf(const world::World& world) {
  return world.bodies.size() + world.geoms.size() + world.joints.size();
}

// A state from the other side: 14 numbers (null for a number that was not
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

class ProtocolEngine : public world::Engine {
 public:
  ProtocolEngine(std::string title, const std::string& where, std::unique_ptr<ProtocolLink> link)
      : name_(std::move(title)), side_(name_ + "'s " + where), link_(std::move(link)) {}

  ~ProtocolEngine() override {
    link_->setDeadline(requestDeadlineSeconds("quit", 0, 0));
    link_->writeLine(R"({"op":"quit"})");
  }

  void build(const world::World& world) override {
    json message = worldMessage("build", world);
    parts_ = partsOf(world);
    takeStates(request(message, requestDeadlineSeconds("build", parts_, 0)));
  }

  void add(const world::World& world, int firstBody, int firstGeom, int firstJoint) override {
    json message = worldMessage("add", world);
    message["first_body"] = firstBody;
    message["first_geom"] = firstGeom;
    message["first_joint"] = firstJoint;
    parts_ = partsOf(world);
    takeStates(request(message, requestDeadlineSeconds("add", parts_, 0)));
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
    const json reply = request({{"op", "step"}, {"count", 1}}, requestDeadlineSeconds("step", parts_, 1));
    takeStates(reply);
    const auto number = [&](const char* key, double fallback) {
      const auto it = reply.find(key);
      return it != reply.end() && it->is_number() ? it->get<double>() : fallback;
    };
    contacts_ = static_cast<int>(number("contacts", -1));
    wall_ = number("engine_wall_s", wall_);
    cpu_ = number("engine_cpu_s", cpu_);
  }

  bool reset() override {
    send({{"op", "reset"}});
    states_.clear();
    notes_.clear();
    contacts_ = -1;
    wall_ = cpu_ = 0;
    return true;
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
  std::string side_;  // "Jolt's Node.js engine server"
  std::unique_ptr<ProtocolLink> link_;
  std::vector<world::BodyState> states_;
  std::vector<std::string> notes_;
  int contacts_ = -1;
  double wall_ = 0, cpu_ = 0;
  std::size_t parts_ = 0;  // bodies, geoms and joints of the world last sent

  // The world as JSON with every body in it, removed ones named apart:
  // worldToJson leaves removed bodies out and renumbers the rest, and the
  // other side must keep the program's indices.
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
    throw world::EngineFailure(side_ + " ended while " + doing + " (" + link_->endedHow() + ")");
  }

  // A message that takes no reply (an edit, new settings) is written within
  // a deadline too: a child that stopped reading cannot hold the program.
  void send(const json& message, double deadline = -1) {
    link_->setDeadline(deadline > 0 ? deadline
                                     : requestDeadlineSeconds(message.value("op", std::string()), parts_, 0));
    if (!link_->writeLine(message.dump())) died("taking a message");
  }

  json request(const json& message, double deadline) {
    send(message, deadline);
    std::string line;
    if (!link_->readLine(line)) died("answering '" + message.value("op", std::string()) + "'");
    json reply;
    try {
      reply = json::parse(line);
    } catch (const json::exception&) {
      throw world::EngineFailure(side_ + " answered what is not JSON: " + line.substr(0, 200));
    }
    if (!reply.is_object()) throw world::EngineFailure(side_ + " answered what is not a reply: " + line.substr(0, 200));
    if (const auto error = reply.find("error"); error != reply.end())
      throw world::EngineError(name_ + ": " + (error->is_string() ? error->get<std::string>() : error->dump()));
    if (const auto notes = reply.find("notes"); notes != reply.end() && notes->is_array())
      for (const json& note : *notes)
        if (note.is_string()) notes_.push_back(note.get<std::string>());
    return reply;
  }

  void takeStates(const json& reply) {
    const auto states = reply.find("states");
    if (states == reply.end() || !states->is_array()) throw world::EngineFailure(side_ + "'s reply has no states");
    states_.resize(states->size());
    for (size_t i = 0; i < states->size(); ++i) {
      if ((*states)[i].is_null()) continue;  // a removed body keeps its last state
      if (!readState((*states)[i], states_[i]))
        throw world::EngineFailure(side_ + " sent a state that is not 14 numbers (body " + std::to_string(i) + ")");
    }
  }
};

}  // namespace

double requestDeadlineSeconds(const std::string& op, std::size_t bodies, long steps) {
  const bool builds = op == "build" || op == "add";
  const double parts = static_cast<double>(bodies), count = static_cast<double>(steps < 0 ? 0 : steps);
  return (builds ? BUILD_BASE_SECONDS : MESSAGE_BASE_SECONDS) + SECONDS_PER_PART * parts +
         count * (SECONDS_PER_STEP + SECONDS_PER_PART_STEP * parts);
}

std::unique_ptr<world::Engine> makeProtocolEngine(const std::string& title, const std::string& where,
                                                  std::unique_ptr<ProtocolLink> link) {
  return std::make_unique<ProtocolEngine>(title, where, std::move(link));
}

}  // namespace odelab::engines
