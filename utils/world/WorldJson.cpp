#include "WorldJson.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "FormatRanges.h"
#include "GhostLaw.h"
#include "JsonDocument.h"
#include "JsonLines.h"
#include "SafeFile.h"
#include "WorldFromMjcf.h"
#include "WorldFromSdf.h"
#include "WorldSettings.h"

namespace odelab::world {

using nlohmann::json;

namespace {

// JSON has no infinity: an unbounded value is the string "infinity" (or "-infinity").
json number(double value) {
  if (std::isinf(value)) return value > 0 ? "infinity" : "-infinity";
  return value;
}

json vec(const Vec3& v) { return json::array({v[0], v[1], v[2]}); }

// What ODE holds of a value the reader allowed can come back a rounding past
// its bound (a joint's anchor at 1e9 m, recomputed from its body's pose): the
// writer puts it back at the bound, so that every export reads back.
double within(double v, double low, double high) { return std::isfinite(v) ? std::min(high, std::max(low, v)) : v; }
json vecWithin(const Vec3& v, double bound) {
  return json::array({within(v[0], -bound, bound), within(v[1], -bound, bound), within(v[2], -bound, bound)});
}
json quat(const Quat& q) { return json::array({q[0], q[1], q[2], q[3]}); }

const std::map<ShapeKind, const char*> SHAPES = {{ShapeKind::Box, "box"},
                                                 {ShapeKind::Sphere, "sphere"},
                                                 {ShapeKind::Plane, "plane"},
                                                 {ShapeKind::Capsule, "capsule"},
                                                 {ShapeKind::Cylinder, "cylinder"}};
const std::map<JointKind, const char*> JOINTS = {
    {JointKind::Ball, "ball"}, {JointKind::Hinge, "hinge"}, {JointKind::Slider, "slider"}, {JointKind::Fixed, "fixed"}};

const std::map<MeasureKind, const char*> MEASURES = {
    {MeasureKind::Energy, "energy"},           {MeasureKind::Momentum, "momentum"},
    {MeasureKind::JointError, "joint_error"},  {MeasureKind::Penetration, "penetration"},
    {MeasureKind::Tunnelling, "tunnelling"},   {MeasureKind::Ballistic, "ballistic"},
    {MeasureKind::Period, "period"},           {MeasureKind::Rest, "rest"},
    {MeasureKind::Probe, "probe"}};
const std::map<GhostLaw, const char*> GHOST_LAWS = {
    {GhostLaw::Ballistic, "ballistic"}, {GhostLaw::Bounce, "bounce"}, {GhostLaw::Pendulum, "pendulum"}};
const std::map<ProbeOf, const char*> PROBE_OF = {{ProbeOf::Position, "position"},
                                                 {ProbeOf::Velocity, "velocity"},
                                                 {ProbeOf::Displacement, "displacement"},
                                                 {ProbeOf::AngularVelocity, "angular_velocity"},
                                                 {ProbeOf::AngularMomentum, "angular_momentum"},
                                                 {ProbeOf::Energy, "energy"}};
const std::map<ProbeTake, const char*> PROBE_TAKE = {
    {ProbeTake::At, "at"}, {ProbeTake::Max, "max"}, {ProbeTake::Min, "min"}, {ProbeTake::FirstCrossing, "first_crossing"}};
const char* const AXES[] = {"x", "y", "z", "magnitude"};

// Edits (insert, delete, replace) between two short words; 99 for a long one.
std::size_t editDistance(const std::string& a, const std::string& b) {
  if (a.size() > 64 || b.size() > 64) return 99;
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// Close enough to be a slip of the keyboard: two edits, one in a short word.
bool nearly(const std::string& typed, const std::string& meant) {
  return typed != meant && editDistance(typed, meant) <= (meant.size() <= 4 ? 1u : 2u);
}

// Reads one JSON object, field by field, naming the path of whatever is wrong
// ("geoms[2].size[1]") and refusing fields it does not know (a typo would
// otherwise be a default silently taken).
class Reader {
 public:
  Reader(JsonValue object, std::string path) : object_(object), path_(std::move(path)) {
    if (!object_.isObject()) fail(path_, "must be an object");
  }
  ~Reader() noexcept(false) {
    if (std::uncaught_exceptions()) return;
    // The first unknown field in the order of the keys' spelling, as it was
    // when the document was nlohmann's (a sorted map): the same file, the same message.
    const std::string_view unknown = firstKey([&](std::string_view key) { return !used(key); });
    if (unknown.data()) {
      std::string meant;
      used_.any([&](std::string_view field) {
        if (nearly(std::string(unknown), std::string(field))) meant = ": did you mean \"" + std::string(field) + "\"?";
        return false;  // the last one near, as before
      });
      fail(path_ + "." + std::string(unknown), "is not a field of this format (doc/world-format.md lists them)" + meant);
    }
  }

  bool has(const char* key) const { return bool(object_.find(key)); }
  std::string at(const char* key) const { return path_ + "." + key; }

  double real(const char* key, double fallback, double low, double high, bool required = false) {
    const JsonValue value = find(key, required);
    return value ? realValue(value, [&] { return at(key); }, low, high) : fallback;
  }
  int integer(const char* key, int fallback, int low, int high, bool required = false) {
    const JsonValue value = find(key, required);
    if (!value) return fallback;
    if (!value.isInteger()) fail(at(key), "must be a whole number");
    // Above 2^63 a signed read would wrap: refuse it as out of range.
    if (value.isUnsigned() && value.whole() > static_cast<unsigned long long>(high))
      fail(at(key), "must be in [" + std::to_string(low) + ", " + std::to_string(high) + "], got " + value.dump());
    const long long v = value.integer();
    if (v < low || v > high) fail(at(key), "must be in [" + std::to_string(low) + ", " + std::to_string(high) + "], got " + std::to_string(v));
    return static_cast<int>(v);
  }
  bool flag(const char* key, bool fallback) {
    const JsonValue value = find(key, false);
    if (!value) return fallback;
    if (!value.isBoolean()) fail(at(key), "must be true or false");
    return value.boolean();
  }
  std::string text(const char* key, const std::string& fallback, bool required = false) {
    const JsonValue value = find(key, required);
    if (!value) return fallback;
    if (!value.isString()) fail(at(key), "must be a string");
    return std::string(value.text());
  }
  // Every item finite and within [-bound, bound] (JSON Schema's "number": no "infinity" here).
  template <size_t N>
  std::array<double, N> reals(const char* key, const std::array<double, N>& fallback, bool required, double bound) {
    return reals<N>(key, fallback, required, -bound, bound);
  }
  template <size_t N>
  std::array<double, N> reals(const char* key, const std::array<double, N>& fallback, bool required, double low, double high) {
    const JsonValue value = find(key, required);
    if (!value) return fallback;
    if (!value.isArray() || value.size() != N) fail(at(key), "must be an array of " + std::to_string(N) + " numbers");
    std::array<double, N> out{};
    for (size_t i = 0; i < N; ++i)
      out[i] = realValue(value[i], [&] { return at(key) + "[" + std::to_string(i) + "]"; }, low, high);
    return out;
  }
  std::uint32_t bits(const char* key) {
    const JsonValue value = find(key, false);
    if (!value) return 0xffffffffu;
    if (!value.isUnsigned() || value.whole() > 0xffffffffull) fail(at(key), "must be a whole number in [0, 4294967295]");
    return static_cast<std::uint32_t>(value.whole());
  }
  JsonValue list(const char* key, bool required) {
    const JsonValue value = find(key, required);
    if (value && !value.isArray()) fail(at(key), "must be an array");
    if (value && value.size() > limits::ITEMS)
      fail(at(key), "holds " + std::to_string(value.size()) + " items; the format allows " + std::to_string(limits::ITEMS));
    return value;
  }
  JsonValue object(const char* key) { return find(key, false); }
  JsonValue value(const char* key) const { return object_.find(key); }

  [[noreturn]] static void fail(const std::string& where, const std::string& what) {
    throw WorldFileError(where.rfind("world.", 0) == 0 ? where.substr(6) : where, what);
  }
  // "infinity" (or "-infinity") only where the range reaches it: a vector,
  // a mass or a step is a finite number, as doc/world.schema.json says.
  // `where()` spells the value's path, only when it is wrong (a string built per number read would
  // be most of a large file's reading time).
  template <class Where>
  static double realValue(JsonValue value, const Where& where, double low, double high) {
    const bool unbounded = std::isinf(low) || std::isinf(high);
    double v;
    if (value.textIs("infinity") || value.textIs("-infinity")) {
      if (!unbounded) fail(where(), "must be a finite number in [" + shortNumber(low) + ", " + shortNumber(high) + "], got " + value.dump());
      v = value.textIs("infinity") ? INFINITE : -INFINITE;
    } else if (value.isNumber()) {
      v = value.real();
    } else {
      fail(where(), unbounded ? "must be a number (or \"infinity\")" : "must be a number");
    }
    if (!(v >= low && v <= high)) fail(where(), "must be in [" + shortNumber(low) + ", " + shortNumber(high) + "], got " + shortNumber(v));
    return v;
  }
  static std::string shortNumber(double v) {
    std::ostringstream text;
    text << v;
    return text.str();
  }

 private:
  JsonValue find(const char* name, bool required) {
    const std::string_view key = name;  // its length measured once
    if (!used(key)) used_.push_back(key);
    const JsonValue found = object_.find(key);
    if (found) return found;
    if (required) {
      // A misspelt field is both missing and unknown: say both.
      const std::string_view typed = firstKey([&](std::string_view k) { return !used(k) && nearly(std::string(k), name); });
      if (typed.data())
        fail(at(name), "is missing; the object has \"" + std::string(typed) + "\", which is not a field of this format: did you mean \"" +
                           name + "\"?");
      fail(at(name), "is missing");
    }
    return {};
  }

  // The first of the object's keys, in the order of their spelling, for which
  // `wanted` holds; a view with no data when none does. One pass.
  template <class Wanted>
  std::string_view firstKey(const Wanted& wanted) const {
    std::string_view first;
    for (std::size_t i = 0; i < object_.size(); ++i) {
      const std::string_view key = object_.key(i);
      if ((!first.data() || key < first) && wanted(key)) first = key;
    }
    return first;
  }

  JsonValue object_;
  std::string path_;
  // The fields asked for (a dozen or so: a list searched beats a set's
  // allocations), with their lengths: comparing with a bare char pointer
  // measured its length each time, for every field of every object. Held in
  // the Reader itself up to FIELDS of them (a world's largest object asks 17),
  // so that reading an object allocates nothing.
  bool used(std::string_view key) const {
    return used_.any([&](std::string_view field) { return key == field; });
  }
  static constexpr std::size_t FIELDS = 24;
  class Fields {
   public:
    void push_back(std::string_view field) {
      if (count_ < FIELDS) fields_[count_++] = field;
      else more_.push_back(field);
    }
    template <class F>
    bool any(const F& f) const {
      for (std::size_t i = 0; i < count_; ++i)
        if (f(fields_[i])) return true;
      for (const std::string_view field : more_)
        if (f(field)) return true;
      return false;
    }
   private:
    std::array<std::string_view, FIELDS> fields_;
    std::size_t count_ = 0;
    std::vector<std::string_view> more_;  // past FIELDS: none in today's format
  };
  Fields used_;
};

Quat unitQuat(Reader& r, const char* key) {
  Quat q = r.reals<4>(key, Quat{1, 0, 0, 0}, false, 2.0);
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (std::abs(n - 1.0) > 1e-6) Reader::fail(r.at(key), "must be a unit quaternion [w, x, y, z]");
  return q;
}

template <class Kind>
Kind named(const std::map<Kind, const char*>& names, const std::string& word, const std::string& where) {
  for (const auto& [kind, name] : names)
    if (word == name) return kind;
  // The list of names spelt out only for the message (once per geom, it was a string built each time).
  std::string known;
  for (const auto& [kind, name] : names) known += (known.empty() ? "" : ", ") + std::string(name);
  Reader::fail(where, "\"" + word + "\" is not one of " + known);
}

// A body named by index, or -1 for none (the static world).
int bodyIndex(Reader& r, const char* key, int bodies) { return r.integer(key, -1, -1, bodies - 1, true); }

// Sylvester's criterion on [xx xy xz; xy yy yz; xz yz zz], on the tensor
// divided by its largest entry, so that no product overflows or underflows.
bool positiveDefinite(const std::array<double, 6>& i) {
  double largest = 0;
  for (double v : i) largest = std::max(largest, std::abs(v));
  if (!(largest > 0) || !std::isfinite(largest)) return false;
  const double xx = i[0] / largest, yy = i[1] / largest, zz = i[2] / largest, xy = i[3] / largest, xz = i[4] / largest,
               yz = i[5] / largest;
  const double minor2 = xx * yy - xy * xy;
  const double det = xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * xz) + xz * (xy * yz - yy * xz);
  return xx > 0 && minor2 > 0 && det > 0;
}

Settings readSettings(JsonValue j) {
  Reader r(j, "settings");
  Settings s;
  // The knobs' ranges (utils/WorldSettings.cpp): what a file sets, a knob can show and move.
  s.step = r.real("step", s.step, ranges::STEP.min, ranges::STEP.max, true);
  s.gravity = r.reals<3>("gravity", s.gravity, true, limits::GRAVITY_COMPONENT);
  const double g = std::sqrt(s.gravity[0] * s.gravity[0] + s.gravity[1] * s.gravity[1] + s.gravity[2] * s.gravity[2]);
  if (!ranges::GRAVITY.contains(g))
    Reader::fail(r.at("gravity"), "its magnitude must be at most " + Reader::shortNumber(ranges::GRAVITY.max) + " m/s^2, got " +
                                      Reader::shortNumber(g));
  s.erp = r.real("erp", s.erp, ranges::ERP.min, ranges::ERP.max);
  s.cfm = r.real("cfm", s.cfm, ranges::CFM.min, ranges::CFM.max);
  const std::string solver = r.text("solver", "quick");
  if (solver != "quick" && solver != "step") Reader::fail(r.at("solver"), "\"" + solver + "\" is not one of quick, step");
  s.quickStep = solver == "quick";
  s.iterations = r.integer("iterations", s.iterations, static_cast<int>(ranges::ITERATIONS.min), static_cast<int>(ranges::ITERATIONS.max));
  s.sorW = r.real("sor_w", s.sorW, ranges::SOR.min, ranges::SOR.max);
  s.contactMaxCorrectingVelocity = r.real("contact_max_correcting_velocity", s.contactMaxCorrectingVelocity, 0.0, INFINITE);
  s.contactSurfaceLayer = r.real("contact_surface_layer", s.contactSurfaceLayer, 0.0, 1.0);
  s.maxContacts = r.integer("max_contacts", s.maxContacts, 1, 64);
  s.space = r.text("space", s.space);
  if (s.space != "simple" && s.space != "hash" && s.space != "sap" && s.space != "quadtree")
    Reader::fail(r.at("space"), "\"" + s.space + "\" is not one of simple, hash, sap, quadtree");
  return s;
}

Body readBody(JsonValue j, const std::string& path) {
  Reader r(j, path);
  Body b;
  b.mass = r.real("mass", b.mass, limits::MASS_MIN, limits::MASS_MAX, true);
  b.inertia = r.reals<6>("inertia", b.inertia, true, limits::INERTIA);
  if (!positiveDefinite(b.inertia))
    Reader::fail(r.at("inertia"), "is not positive definite (a real body's inertia tensor is: xx, yy, zz > 0 and every "
                                  "leading minor > 0), as ODE's dMassCheck requires");
  b.position = r.reals<3>("position", b.position, true, limits::LENGTH);
  b.orientation = unitQuat(r, "orientation");
  b.linearVelocity = r.reals<3>("linear_velocity", b.linearVelocity, false, limits::SPEED);
  b.angularVelocity = r.reals<3>("angular_velocity", b.angularVelocity, false, limits::ANGULAR_SPEED);
  b.enabled = r.flag("enabled", true);
  b.kinematic = r.flag("kinematic", false);
  b.gravity = r.flag("gravity", true);
  b.maxAngularSpeed = r.real("max_angular_speed", INFINITE, 0.0, INFINITE);
  if (const JsonValue a = r.object("auto_disable")) {
    Reader ad(a, path + ".auto_disable");
    b.autoDisable.on = ad.flag("on", false);
    b.autoDisable.linearThreshold = ad.real("linear_threshold", b.autoDisable.linearThreshold, 0.0, INFINITE);
    b.autoDisable.angularThreshold = ad.real("angular_threshold", b.autoDisable.angularThreshold, 0.0, INFINITE);
    b.autoDisable.steps = ad.integer("steps", b.autoDisable.steps, 0, 1 << 30);
    b.autoDisable.time = ad.real("time", b.autoDisable.time, 0.0, INFINITE);
    b.autoDisable.averageSamples = ad.integer("average_samples", b.autoDisable.averageSamples, 1, 1 << 20);
  }
  return b;
}

Geom readGeom(JsonValue j, const std::string& path, int bodies) {
  Reader r(j, path);
  Geom g;
  g.shape = named(SHAPES, r.text("shape", "", true), r.at("shape"));
  g.body = bodyIndex(r, "body", bodies);
  switch (g.shape) {
    case ShapeKind::Box:
      g.size = r.reals<3>("size", g.size, true, limits::SIDE_MIN, limits::SIDE_MAX);
      break;
    case ShapeKind::Sphere:
      g.size = {r.real("radius", 0, limits::SIDE_MIN, limits::SIDE_MAX, true), 0, 0};
      break;
    case ShapeKind::Capsule:
    case ShapeKind::Cylinder:
      g.size = {r.real("radius", 0, limits::SIDE_MIN, limits::SIDE_MAX, true), r.real("length", 0, 0, limits::SIDE_MAX, true), 0};
      break;
    case ShapeKind::Plane:
      g.plane = r.reals<4>("plane", g.plane, true, limits::LENGTH);
      if (std::abs(std::sqrt(g.plane[0] * g.plane[0] + g.plane[1] * g.plane[1] + g.plane[2] * g.plane[2]) - 1.0) > 1e-6)
        Reader::fail(r.at("plane"), "(a, b, c) must be a unit normal");
      if (g.body >= 0) Reader::fail(r.at("body"), "a plane is static: it has no body");
      break;
  }
  if (g.shape != ShapeKind::Plane) {
    g.position = r.reals<3>("position", g.position, false, limits::LENGTH);
    g.orientation = unitQuat(r, "orientation");
  }
  g.category = r.bits("category");
  g.collide = r.bits("collide");
  return g;
}

Joint readJoint(JsonValue j, const std::string& path, int bodies) {
  Reader r(j, path);
  Joint k;
  k.kind = named(JOINTS, r.text("type", "", true), r.at("type"));
  k.body1 = bodyIndex(r, "body1", bodies);
  k.body2 = bodyIndex(r, "body2", bodies);
  if (k.body1 < 0 && k.body2 < 0) Reader::fail(path, "joins no body (body1 and body2 are both -1)");
  if (k.body1 == k.body2) Reader::fail(path, "joins body " + std::to_string(k.body1) + " to itself");
  if (k.kind == JointKind::Ball || k.kind == JointKind::Hinge) k.anchor = r.reals<3>("anchor", k.anchor, true, limits::LENGTH);
  if (k.kind == JointKind::Hinge || k.kind == JointKind::Slider) {
    k.axis = r.reals<3>("axis", k.axis, true, limits::LENGTH);
    const double n = std::sqrt(k.axis[0] * k.axis[0] + k.axis[1] * k.axis[1] + k.axis[2] * k.axis[2]);
    if (!(n > 0)) Reader::fail(r.at("axis"), "must not be zero");
    k.lowStop = r.real("low_stop", -INFINITE, -INFINITE, INFINITE);
    k.highStop = r.real("high_stop", INFINITE, -INFINITE, INFINITE);
  }
  // ODE (0.16) keeps an ERP and CFM of a joint's own for ball and fixed joints
  // only (dParamERP, dParamCFM); a hinge's or slider's rows take the world's,
  // their dParamCFM is the motor's and dParamStopERP / dParamStopCFM act only
  // at a stop. Accepted there, the field would be read and change nothing.
  if (k.kind == JointKind::Hinge || k.kind == JointKind::Slider)
    for (const char* key : {"erp", "cfm"})
      if (r.has(key))
        Reader::fail(r.at(key), std::string("a ") + jointName(k.kind) + " joint has no " + key +
                                    " of its own in ODE (its rows take settings." + key +
                                    "; dParamCFM is a motor's, dParamStopERP / dParamStopCFM act only at a stop): "
                                    "set settings." + key + ", or use a ball or fixed joint");
  k.erp = r.real("erp", k.erp, 0.0, 1.0);
  k.cfm = r.real("cfm", k.cfm, 0.0, 1.0);
  return k;
}

Surface readSurface(JsonValue j, const std::string& path) {
  Reader r(j, path);
  Surface s;
  s.mu = r.real("mu", s.mu, 0.0, INFINITE, true);
  s.bounce = r.has("restitution");
  s.restitution = r.real("restitution", 0.0, 0.0, 1.0);
  s.bounceVelocity = r.real("bounce_velocity", 0.0, 0.0, INFINITE);
  if (!s.bounce && r.has("bounce_velocity")) Reader::fail(r.at("bounce_velocity"), "is given without restitution");
  s.softErp = r.has("soft_erp");
  s.softErpValue = r.real("soft_erp", 0.0, 0.0, 1.0);
  s.softCfm = r.has("soft_cfm");
  s.softCfmValue = r.real("soft_cfm", 0.0, 0.0, 1.0);
  s.approx1 = r.flag("friction_pyramid", false);
  return s;
}

json writeSurface(const Surface& s) {
  json j = {{"mu", number(s.mu)}};
  if (s.bounce) {
    j["restitution"] = s.restitution;
    j["bounce_velocity"] = s.bounceVelocity;
  }
  if (s.softErp) j["soft_erp"] = s.softErpValue;
  if (s.softCfm) j["soft_cfm"] = s.softCfmValue;
  if (s.approx1) j["friction_pyramid"] = true;
  return j;
}

// A probe (doc/world-format.md): what it reads, how the run's readings make
// one figure, and the answer it is held to. A field that its `take` does not
// use is refused, naming the take, rather than read and ignored.
void readProbe(Reader& r, Measure& m, int bodies) {
  m.of = named(PROBE_OF, r.text("of", "", true), r.at("of"));
  if (m.of == ProbeOf::Energy) {
    // The world's energy: one number, of every body together.
    for (const char* key : {"body", "axis"})
      if (r.has(key)) Reader::fail(r.at(key), "is not used by of \"energy\" (the world's mechanical energy, of every body)");
    m.body = -1;
    m.axis = MAGNITUDE;
  } else {
    m.body = r.integer("body", -1, 0, bodies - 1, true);
    const std::string axis = r.text("axis", "", true);
    m.axis = -1;
    for (int k = 0; k < 4; ++k)
      if (axis == AXES[k]) m.axis = k;
    if (m.axis < 0) Reader::fail(r.at("axis"), "\"" + axis + "\" is not one of x, y, z, magnitude");
  }
  if (m.axis == MAGNITUDE && m.of == ProbeOf::Position)
    Reader::fail(r.at("axis"), "a position has no magnitude of its own (its distance from the origin): read \"displacement\"");
  m.take = named(PROBE_TAKE, r.text("take", "at"), r.at("take"));
  const char* take = PROBE_TAKE.at(m.take);
  const auto only = [&](const char* key, bool allowed) {
    if (r.has(key) && !allowed) Reader::fail(r.at(key), std::string("is not used by take \"") + take + "\"");
  };
  only("at", m.take == ProbeTake::At);
  only("from", m.take != ProbeTake::At);
  only("until", m.take != ProbeTake::At);
  only("value", m.take == ProbeTake::FirstCrossing);
  m.at = r.real("at", m.at, 0.0, limits::TIME);
  m.from = r.real("from", m.from, 0.0, limits::TIME);
  m.until = r.real("until", m.until, 0.0, limits::TIME);
  if (r.has("from") && r.has("until") && !(m.until > m.from)) Reader::fail(r.at("until"), "must be after from");
  m.value = r.real("value", m.value, -limits::READING, limits::READING, m.take == ProbeTake::FirstCrossing);
  m.expect = r.real("expect", m.expect, -limits::READING, limits::READING);
  m.tolerance = r.real("tolerance", m.tolerance, 0.0, limits::READING);
  m.relativeTolerance = r.real("relative_tolerance", m.relativeTolerance, 0.0, limits::RELATIVE_TOLERANCE);
  const bool tolerance = r.has("tolerance"), relative = r.has("relative_tolerance");
  if (tolerance && relative) Reader::fail(r.at("relative_tolerance"), "is given with tolerance: state one of them");
  if (r.has("expect") && !tolerance && !relative)
    Reader::fail(r.at("expect"), "needs a tolerance (absolute, in the reading's unit) or a relative_tolerance (of |expect|)");
  if (!r.has("expect") && (tolerance || relative))
    Reader::fail(r.at(tolerance ? "tolerance" : "relative_tolerance"), "is given without expect");
  if (relative && m.expect == 0) Reader::fail(r.at("relative_tolerance"), "is relative to expect, which is 0: give tolerance");
}

Measure readMeasure(JsonValue j, const std::string& path, const World& w) {
  Reader r(j, path);
  Measure m;
  m.kind = named(MEASURES, r.text("kind", "", true), r.at("kind"));
  const int bodies = static_cast<int>(w.bodies.size());
  switch (m.kind) {
    case MeasureKind::Energy:
      m.scale = r.real("scale", 0.0, 1e-300, INFINITE);
      m.expect = r.real("expect", m.expect, -INFINITE, INFINITE);
      break;
    case MeasureKind::Momentum:
      m.scale = r.real("linear_scale", 0.0, 1e-300, INFINITE);
      m.angularScale = r.real("angular_scale", 0.0, 1e-300, INFINITE);
      break;
    case MeasureKind::Tunnelling: {
      m.geom = r.integer("geom", -1, 0, static_cast<int>(w.geoms.size()) - 1, true);
      const Geom& g = w.geoms[static_cast<size_t>(m.geom)];
      if (g.body >= 0 || (g.shape != ShapeKind::Box && g.shape != ShapeKind::Plane))
        Reader::fail(r.at("geom"), "must name a static box or plane (the wall bodies might pass through)");
      if (r.has("expect")) m.expect = r.integer("expect", 0, 0, bodies);
      break;
    }
    case MeasureKind::Ballistic:
      m.body = r.integer("body", -1, 0, bodies - 1, true);
      m.until = r.real("until", INFINITE, 0.0, INFINITE);
      break;
    case MeasureKind::Period: {
      m.body = r.integer("body", -1, 0, bodies - 1, true);
      const std::string axis = r.text("axis", "", true);
      if (axis != "x" && axis != "y" && axis != "z") Reader::fail(r.at("axis"), "\"" + axis + "\" is not one of x, y, z");
      m.axis = axis[0] - 'x';
      m.about = r.real("about", 0.0, -INFINITE, INFINITE, true);
      m.expected = r.real("expected", 0.0, 1e-9, INFINITE, true);
      break;
    }
    case MeasureKind::Rest:
      m.speed = r.real("speed", m.speed, 0.0, INFINITE);
      m.angularSpeed = r.real("angular_speed", m.angularSpeed, 0.0, INFINITE);
      m.hold = r.real("hold", m.hold, 0.0, INFINITE);
      if (r.has("expect") && r.value("expect").isString()) {
        if (r.text("expect", "") != "never")
          Reader::fail(r.at("expect"), "must be a time to rest (s) or \"never\" (the body keeps moving)");
        m.expectNever = true;
      } else {
        m.expect = r.real("expect", m.expect, 0.0, INFINITE);
      }
      break;
    case MeasureKind::Probe: readProbe(r, m, bodies); break;
    case MeasureKind::JointError:
    case MeasureKind::Penetration:
      break;
  }
  if (m.kind == MeasureKind::Ballistic || m.kind == MeasureKind::Period || m.kind == MeasureKind::Probe) {
    m.name = r.text("name", std::string(MEASURES.at(m.kind)) + (m.body >= 0 ? std::to_string(m.body) : std::string("_energy")));
    if (m.name.empty() || m.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos)
      Reader::fail(r.at("name"), "must be lower-case letters, digits and _ (it names metrics)");
  }
  return m;
}

Event readEvent(JsonValue j, const std::string& path, const World& w) {
  Reader r(j, path);
  Event e;
  e.at = r.real("at", 0.0, 0.0, INFINITE, true);
  const int last = static_cast<int>(w.bodies.size()) - 1;
  if (r.has("drop") == r.has("push")) Reader::fail(path, "must have one of \"drop\" or \"push\" (a body's index)");
  e.kind = r.has("drop") ? EventKind::Drop : EventKind::Push;
  e.body = r.integer(e.kind == EventKind::Drop ? "drop" : "push", 0, 0, last, true);
  if (e.kind == EventKind::Push) e.impulse = r.reals<3>("impulse", e.impulse, true, limits::IMPULSE);
  return e;
}

json writeMeasure(const Measure& m) {
  json j = {{"kind", MEASURES.at(m.kind)}};
  switch (m.kind) {
    case MeasureKind::Energy:
      if (m.scale > 0) j["scale"] = m.scale;
      break;
    case MeasureKind::Momentum:
      if (m.scale > 0) j["linear_scale"] = m.scale;
      if (m.angularScale > 0) j["angular_scale"] = m.angularScale;
      break;
    case MeasureKind::Tunnelling: j["geom"] = m.geom; break;
    case MeasureKind::Ballistic:
      j["body"] = m.body;
      j["name"] = m.name;
      if (!std::isinf(m.until)) j["until"] = m.until;
      break;
    case MeasureKind::Period:
      j["body"] = m.body;
      j["name"] = m.name;
      j["axis"] = std::string(1, static_cast<char>('x' + m.axis));
      j["about"] = m.about;
      j["expected"] = m.expected;
      break;
    case MeasureKind::Rest:
      j["speed"] = m.speed;
      j["angular_speed"] = m.angularSpeed;
      j["hold"] = m.hold;
      break;
    case MeasureKind::Probe:
      if (m.of != ProbeOf::Energy) {
        j["body"] = m.body;
        j["axis"] = AXES[m.axis];
      }
      j["name"] = m.name;
      j["of"] = PROBE_OF.at(m.of);
      j["take"] = PROBE_TAKE.at(m.take);
      if (!std::isnan(m.at)) j["at"] = m.at;
      if (m.take != ProbeTake::At) {
        if (m.from > 0) j["from"] = m.from;
        if (!std::isinf(m.until)) j["until"] = m.until;
      }
      if (m.take == ProbeTake::FirstCrossing) j["value"] = m.value;
      if (!std::isnan(m.tolerance)) j["tolerance"] = m.tolerance;
      if (!std::isnan(m.relativeTolerance)) j["relative_tolerance"] = m.relativeTolerance;
      break;
    case MeasureKind::JointError:
    case MeasureKind::Penetration:
      break;
  }
  if (m.expectNever) j["expect"] = "never";
  if (!std::isnan(m.expect))
    j["expect"] = m.kind == MeasureKind::Tunnelling ? json(static_cast<int>(m.expect)) : json(m.expect);  // a count
  return j;
}

}  // namespace

bool Surface::operator==(const Surface& o) const {
  return mu == o.mu && bounce == o.bounce && restitution == o.restitution && bounceVelocity == o.bounceVelocity &&
         softErp == o.softErp && softErpValue == o.softErpValue && softCfm == o.softCfm &&
         softCfmValue == o.softCfmValue && approx1 == o.approx1;
}

const char* shapeName(ShapeKind kind) { return SHAPES.at(kind); }
const char* jointName(JointKind kind) { return JOINTS.at(kind); }
const char* measureName(MeasureKind kind) { return MEASURES.at(kind); }
const char* ghostLawName(GhostLaw law) { return GHOST_LAWS.at(law); }

const Surface& World::surfaceBetween(int geom1, int geom2) const {
  if (geom1 > geom2) std::swap(geom1, geom2);
  for (const PairSurface& pair : pairSurfaces)
    if (pair.geom1 == geom1 && pair.geom2 == geom2) return surfaces[pair.surface];
  return surfaces[defaultSurface];
}

bool World::mayTouch(int geom1, int geom2) const {
  const Geom& a = geoms[geom1];
  const Geom& b = geoms[geom2];
  if (a.body < 0 && b.body < 0) return false;
  if (a.body == b.body) return false;
  if (!((a.category & b.collide) || (b.category & a.collide))) return false;
  if (a.body >= 0 && b.body >= 0)
    for (const Joint& joint : joints)
      if ((joint.body1 == a.body && joint.body2 == b.body) || (joint.body1 == b.body && joint.body2 == a.body))
        return false;
  return true;
}

namespace {

World worldFromParsed(JsonValue root) {
  World w;
  Reader r(root, "world");
  const std::string format = r.text("format", "", true);
  if (format != "odelab-world") Reader::fail(r.at("format"), "must be \"odelab-world\", got \"" + format + "\"");
  w.version = r.integer("version", 0, 0, 1 << 30, true);
  if (w.version != FORMAT_VERSION)
    Reader::fail(r.at("version"), "this program reads version " + std::to_string(FORMAT_VERSION) + ", the file is version " +
                                      std::to_string(w.version));
  r.text("$schema", "");  // where an editor finds doc/world.schema.json; the reader needs none
  w.scene = r.text("scene", "");
  w.title = r.text("title", "");
  w.description = r.text("description", "");
  w.duration = r.real("duration", 0.0, limits::DURATION_MIN, limits::TIME);
  w.time = r.real("time", 0.0, 0.0, INFINITE);
  const JsonValue settings = r.object("settings");
  if (!settings) Reader::fail(r.at("settings"), "is missing");
  w.settings = readSettings(settings);
  if (const JsonValue bodies = r.list("bodies", false)) {
    w.bodies.reserve(bodies.size());
    for (size_t i = 0; i < bodies.size(); ++i) w.bodies.push_back(readBody(bodies[i], "bodies[" + std::to_string(i) + "]"));
  }
  const int bodyCount = static_cast<int>(w.bodies.size());
  const JsonValue geoms = r.list("geoms", true);
  w.geoms.reserve(geoms.size());
  for (size_t i = 0; i < geoms.size(); ++i)
    w.geoms.push_back(readGeom(geoms[i], "geoms[" + std::to_string(i) + "]", bodyCount));
  if (const JsonValue joints = r.list("joints", false))
    for (size_t i = 0; i < joints.size(); ++i)
      w.joints.push_back(readJoint(joints[i], "joints[" + std::to_string(i) + "]", bodyCount));
  const JsonValue surfaces = r.list("surfaces", true);
  if (surfaces.size() == 0) Reader::fail(r.at("surfaces"), "needs at least one surface");
  for (size_t i = 0; i < surfaces.size(); ++i)
    w.surfaces.push_back(readSurface(surfaces[i], "surfaces[" + std::to_string(i) + "]"));
  const int surfaceCount = static_cast<int>(w.surfaces.size());
  w.defaultSurface = r.integer("default_surface", 0, 0, surfaceCount - 1);
  const int geomCount = static_cast<int>(w.geoms.size());
  if (const JsonValue pairs = r.list("pair_surfaces", false))
    for (size_t i = 0; i < pairs.size(); ++i) {
      const std::string where = "pair_surfaces[" + std::to_string(i) + "]";
      Reader p(pairs[i], where);
      const std::array<double, 2> g = p.reals<2>("geoms", {0, 0}, true, limits::ITEMS);
      PairSurface pair;
      for (int k = 0; k < 2; ++k)
        if (g[k] != std::floor(g[k]) || g[k] < 0 || g[k] >= geomCount)
          Reader::fail(p.at("geoms"), "must name two geoms by index in [0, " + std::to_string(geomCount - 1) + "]");
      pair.geom1 = static_cast<int>(std::min(g[0], g[1]));
      pair.geom2 = static_cast<int>(std::max(g[0], g[1]));
      if (pair.geom1 == pair.geom2) Reader::fail(p.at("geoms"), "names one geom twice");
      pair.surface = p.integer("surface", 0, 0, surfaceCount - 1, true);
      w.pairSurfaces.push_back(pair);
    }
  if (const JsonValue measures = r.list("measures", false)) {
    std::set<std::string> kinds;
    for (size_t i = 0; i < measures.size(); ++i) {
      const std::string where = "measures[" + std::to_string(i) + "]";
      w.measures.push_back(readMeasure(measures[i], where, w));
      const Measure& m = w.measures.back();
      // Two of a kind would write the same metrics (ballistic and period: the same name).
      const std::string key = m.name.empty() ? measureName(m.kind) : m.name;
      if (!kinds.insert(key).second) Reader::fail(where, "measures \"" + key + "\" a second time: its metrics would clash");
    }
  }
  if (const JsonValue events = r.list("events", false)) {
    std::set<int> dropped;
    for (size_t i = 0; i < events.size(); ++i) {
      const std::string where = "events[" + std::to_string(i) + "]";
      w.events.push_back(readEvent(events[i], where, w));
      const Event& e = w.events.back();
      if (i > 0 && e.at < w.events[i - 1].at) Reader::fail(where + ".at", "events must be in time order");
      if (e.kind == EventKind::Drop && !dropped.insert(e.body).second)
        Reader::fail(where + ".drop", "body " + std::to_string(e.body) + " is dropped twice");
    }
    // Each event looked at once (a file of 100k events reads in linear time).
    std::vector<bool> jointed(w.bodies.size(), false);
    for (const Joint& j : w.joints)
      for (int b : {j.body1, j.body2})
        if (b >= 0) jointed[static_cast<size_t>(b)] = true;
    for (size_t i = 0; i < w.events.size(); ++i) {
      const Event& e = w.events[i];
      const std::string where = "events[" + std::to_string(i) + "]";
      if (e.kind == EventKind::Drop && jointed[static_cast<size_t>(e.body)])
        Reader::fail(where + ".drop", "body " + std::to_string(e.body) + " has a joint; only a free body can be dropped in");
    }
    std::vector<bool> droppedLater(w.bodies.size(), false);
    for (size_t i = w.events.size(); i-- > 0;) {
      const Event& e = w.events[i];
      if (e.kind == EventKind::Drop) droppedLater[static_cast<size_t>(e.body)] = true;
      else if (droppedLater[static_cast<size_t>(e.body)])
        Reader::fail("events[" + std::to_string(i) + "].push", "body " + std::to_string(e.body) + " is pushed before it is dropped in");
    }
  }
  // Every body needs a geom: the programs make a body with its first geom, and
  // the engines and the exporter find bodies through their geoms.
  std::vector<bool> hasGeom(w.bodies.size(), false);
  for (const Geom& g : w.geoms)
    if (g.body >= 0) hasGeom[static_cast<size_t>(g.body)] = true;
  for (int b = 0; b < bodyCount; ++b)
    if (!hasGeom[static_cast<size_t>(b)])
      Reader::fail("bodies[" + std::to_string(b) + "]",
                   "has no geom: every body needs one (a body held only by a joint can carry a small sphere that collides "
                   "with nothing, \"collide\": 0)");
  // Last: whether the law fits asks of the bodies, geoms, joints, surfaces and events.
  if (const JsonValue ghost = r.object("ghost")) {
    Reader g(ghost, "ghost");
    w.ghost.on = true;
    w.ghost.body = g.integer("body", -1, 0, bodyCount - 1, true);
    w.ghost.law = named(GHOST_LAWS, g.text("law", "", true), g.at("law"));
    const GhostRefusal refusal = ghostRefusal(w);
    if (!refusal.field.empty()) Reader::fail(g.at(refusal.field.c_str()), refusal.reason);
  }
  return w;
}

// " (line L)" for the first line holding the token an error quotes ('1e400'), or "".
std::string numberLine(const std::string& text, const std::string& message) {
  const std::size_t open = message.find('\'');
  const std::size_t close = message.find('\'', open + 1);
  if (open == std::string::npos || close == std::string::npos) return "";
  const std::size_t at = text.find(message.substr(open + 1, close - open - 1));
  if (at == std::string::npos) return "";
  return " (line " + std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')) + ")";
}

// nlohmann's message without its "[json.exception.parse_error.101] " tag.
std::string untagged(const char* message) {
  const std::string text = message;
  const std::size_t tag = text.rfind("[json.exception.", 0) == 0 ? text.find("] ") : std::string::npos;
  return tag == std::string::npos ? text : text.substr(tag + 2);
}

// The text's shape refused (nested too deep, a key given twice, a missing
// comma), with its line: JsonLines' scan, a second linear pass, made only
// when the text is refused, since a text that reads needs no line.
[[noreturn]] void refuseShape(const JsonShape& shape) {
  if (shape.tooDeepLine)
    throw WorldFileError("line " + std::to_string(shape.tooDeepLine) + ": arrays and objects nested deeper than " +
                         std::to_string(MAX_JSON_DEPTH) + " (a world file needs 4)");
  throw WorldFileError("line " + std::to_string(shape.duplicateLine) + ": " + shape.duplicatePath +
                       ": is given twice in one object (which one was meant?)");
}

}  // namespace

World worldFromJson(const std::string& text) {
  // The bound the table's offsets rest on: a world text is at most a world file's size.
  if (text.size() > limits::BYTES)
    throw WorldFileError("the world text holds " + std::to_string(text.size()) + " bytes; the format allows " +
                         std::to_string(limits::BYTES));
  // One pass: nlohmann's lexer into a flat table (JsonDocument.h), which
  // stops at nesting beyond any world's and notes a key given twice (which
  // nlohmann would take silently: the last wins). What is refused is then
  // placed by one more linear pass (JsonLines.h), which also says a missing
  // comma where it is (nlohmann says it at the next token).
  std::optional<JsonDocument> document;
  try {
    document.emplace(text);
  } catch (const json::parse_error& error) {
    const JsonShape shape = scanJsonShape(text);
    if (shape.tooDeepLine) refuseShape(shape);
    // Where the scan saw a value followed by neither ',' nor a closer, and
    // nlohmann stopped there too, the mistake is at the end of that value.
    if (shape.missingLine && error.byte >= shape.missingAt)
      throw WorldFileError("line " + std::to_string(shape.missingLine) + ": a comma or '" + shape.missingCloser +
                           "' is missing after " + shape.missingAfter);
    throw WorldFileError(std::string("not JSON: ") + untagged(error.what()));
  } catch (const json::exception& error) {
    const JsonShape shape = scanJsonShape(text);
    if (shape.tooDeepLine) refuseShape(shape);
    // A number beyond a double's range: nlohmann gives no position, so the line is the number's.
    throw WorldFileError(std::string("not a usable number: ") + untagged(error.what()) + numberLine(text, error.what()));
  }
  const JsonDocumentProblems& problems = document->problems();
  if (problems.tooDeep || problems.duplicateKey) {
    const JsonShape shape = scanJsonShape(text);
    if (shape.tooDeepLine || shape.duplicateLine) refuseShape(shape);
    // The scan compares keys as written; nlohmann's, read with their escapes ("\u0061" is "a").
    if (problems.tooDeep)
      throw WorldFileError("arrays and objects nested deeper than " + std::to_string(MAX_JSON_DEPTH) + " (a world file needs 4)");
    throw WorldFileError("\"" + problems.duplicate + "\": is given twice in one object (which one was meant?)");
  }
  try {
    return worldFromParsed(document->root());
  } catch (const WorldFileError& error) {
    if (error.field().empty()) throw;
    const int line = lineOfPath(text, error.field());
    throw WorldFileError(line > 0 ? "line " + std::to_string(line) + ": " + error.what() : error.what());
  }
}

std::string worldToJson(const World& world) {
  // Removed bodies and their geoms and joints are left out; the rest renumbered.
  std::vector<int> bodyIndex(world.bodies.size(), -1);
  json bodies = json::array();
  for (size_t i = 0; i < world.bodies.size(); ++i) {
    const Body& b = world.bodies[i];
    if (b.removed) continue;
    bodyIndex[i] = static_cast<int>(bodies.size());
    json j = {{"mass", b.mass},
              {"inertia", json::array({b.inertia[0], b.inertia[1], b.inertia[2], b.inertia[3], b.inertia[4], b.inertia[5]})},
              {"position", vecWithin(b.position, limits::LENGTH)},
              {"orientation", quat(b.orientation)},
              {"linear_velocity", vecWithin(b.linearVelocity, limits::SPEED)},
              {"angular_velocity", vecWithin(b.angularVelocity, limits::ANGULAR_SPEED)}};
    if (!b.enabled) j["enabled"] = false;
    if (b.kinematic) j["kinematic"] = true;
    if (!b.gravity) j["gravity"] = false;
    if (!std::isinf(b.maxAngularSpeed)) j["max_angular_speed"] = b.maxAngularSpeed;
    if (b.autoDisable.on)
      j["auto_disable"] = {{"on", true},
                           {"linear_threshold", b.autoDisable.linearThreshold},
                           {"angular_threshold", b.autoDisable.angularThreshold},
                           {"steps", b.autoDisable.steps},
                           {"time", b.autoDisable.time},
                           {"average_samples", b.autoDisable.averageSamples}};
    bodies.push_back(j);
  }
  auto bodyRef = [&](int b) { return b < 0 ? -1 : bodyIndex[b]; };
  std::vector<int> geomIndex(world.geoms.size(), -1);
  json geoms = json::array();
  for (size_t i = 0; i < world.geoms.size(); ++i) {
    const Geom& g = world.geoms[i];
    if (g.body >= 0 && world.bodies[g.body].removed) continue;
    geomIndex[i] = static_cast<int>(geoms.size());
    json j = {{"shape", shapeName(g.shape)}, {"body", bodyRef(g.body)}};
    switch (g.shape) {
      case ShapeKind::Box: j["size"] = vec(g.size); break;
      case ShapeKind::Sphere: j["radius"] = g.size[0]; break;
      case ShapeKind::Capsule:
      case ShapeKind::Cylinder:
        j["radius"] = g.size[0];
        j["length"] = g.size[1];
        break;
      case ShapeKind::Plane: j["plane"] = json::array({g.plane[0], g.plane[1], g.plane[2], g.plane[3]}); break;
    }
    if (g.shape != ShapeKind::Plane) {
      j["position"] = vecWithin(g.position, limits::LENGTH);
      j["orientation"] = quat(g.orientation);
    }
    if (g.category != 0xffffffffu) j["category"] = g.category;
    if (g.collide != 0xffffffffu) j["collide"] = g.collide;
    geoms.push_back(j);
  }
  json joints = json::array();
  for (const Joint& k : world.joints) {
    if ((k.body1 >= 0 && world.bodies[k.body1].removed) || (k.body2 >= 0 && world.bodies[k.body2].removed)) continue;
    json j = {{"type", jointName(k.kind)}, {"body1", bodyRef(k.body1)}, {"body2", bodyRef(k.body2)}};
    if (k.kind == JointKind::Ball || k.kind == JointKind::Hinge) j["anchor"] = vecWithin(k.anchor, limits::LENGTH);
    if (k.kind == JointKind::Hinge || k.kind == JointKind::Slider) {
      j["axis"] = vecWithin(k.axis, limits::LENGTH);
      if (!std::isinf(k.lowStop)) j["low_stop"] = k.lowStop;
      if (!std::isinf(k.highStop)) j["high_stop"] = k.highStop;
    }
    if (!std::isnan(k.erp)) j["erp"] = k.erp;
    if (!std::isnan(k.cfm)) j["cfm"] = k.cfm;
    joints.push_back(j);
  }
  json surfaces = json::array();
  for (const Surface& s : world.surfaces) surfaces.push_back(writeSurface(s));
  json pairs = json::array();
  for (const PairSurface& p : world.pairSurfaces) {
    if (geomIndex[p.geom1] < 0 || geomIndex[p.geom2] < 0) continue;
    pairs.push_back({{"geoms", json::array({geomIndex[p.geom1], geomIndex[p.geom2]})}, {"surface", p.surface}});
  }
  const Settings& s = world.settings;
  json settings = {{"step", s.step},
                   {"gravity", vec(s.gravity)},
                   {"erp", s.erp},
                   {"cfm", s.cfm},
                   {"solver", s.quickStep ? "quick" : "step"},
                   {"iterations", s.iterations},
                   {"sor_w", s.sorW},
                   {"contact_max_correcting_velocity", number(s.contactMaxCorrectingVelocity)},
                   {"contact_surface_layer", s.contactSurfaceLayer},
                   {"max_contacts", s.maxContacts},
                   {"space", s.space}};
  json root = {{"format", "odelab-world"}, {"version", FORMAT_VERSION}};
  if (!world.scene.empty()) root["scene"] = world.scene;
  if (!world.title.empty()) root["title"] = world.title;
  if (!world.description.empty()) root["description"] = world.description;
  if (world.duration > 0) root["duration"] = world.duration;
  root["time"] = world.time;
  root["settings"] = settings;
  root["bodies"] = bodies;
  root["geoms"] = geoms;
  root["joints"] = joints;
  root["surfaces"] = surfaces;
  root["default_surface"] = world.defaultSurface;
  root["pair_surfaces"] = pairs;
  // Measures and events name bodies and geoms by index: renumbered as above,
  // and left out where what they name was removed.
  if (!world.measures.empty()) {
    json measures = json::array();
    for (Measure m : world.measures) {
      if ((m.body >= 0 && bodyRef(m.body) < 0) || (m.geom >= 0 && geomIndex[m.geom] < 0)) continue;
      if (m.body >= 0) m.body = bodyRef(m.body);
      if (m.geom >= 0) m.geom = geomIndex[m.geom];
      measures.push_back(writeMeasure(m));
    }
    root["measures"] = measures;
  }
  if (!world.events.empty()) {
    json events = json::array();
    for (const Event& e : world.events) {
      if (bodyRef(e.body) < 0) continue;
      json j = {{"at", e.at}};
      if (e.kind == EventKind::Drop) {
        j["drop"] = bodyRef(e.body);
      } else {
        j["push"] = bodyRef(e.body);
        j["impulse"] = vec(e.impulse);
      }
      events.push_back(j);
    }
    root["events"] = events;
  }
  if (world.ghost.on && bodyRef(world.ghost.body) >= 0)
    root["ghost"] = {{"body", bodyRef(world.ghost.body)}, {"law", ghostLawName(world.ghost.law)}};
  // 17 significant digits: every double comes back as the same double.
  return root.dump(1) + "\n";
}

World readWorldFile(const std::string& path) {
  // A world of thousands of bodies is a few MB; 64 MB leaves room and stops /dev/zero-like files.
  std::string text;
  try {
    text = readBoundedFile(path, limits::BYTES, "the world file");
  } catch (const ReadRefused& error) {
    throw WorldFileError(error.what());
  }
  if (looksLikeSdf(path, text)) return worldFromSdf(path);
  if (looksLikeMjcf(path, text)) return worldFromMjcf(path);
  try {
    return worldFromJson(text);
  } catch (const WorldFileError& error) {
    throw WorldFileError(path + ": " + error.what());
  }
}

}  // namespace odelab::world
