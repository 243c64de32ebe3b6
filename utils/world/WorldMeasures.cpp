#include "WorldMeasures.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "MechanicalEnergy.h"

namespace odelab::world {

namespace {

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

double norm(const double* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const double* a, const double* b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 vec(const dReal* v) { return {v[0], v[1], v[2]}; }

bool has(const World& world, MeasureKind kind) {
  return std::any_of(world.measures.begin(), world.measures.end(), [&](const Measure& m) { return m.kind == kind; });
}

// The body's angular momentum about its centre of mass, world frame: R I R^T w.
Vec3 spin(dBodyID body) {
  dMass mass;
  dBodyGetMass(body, &mass);
  const dReal* w = dBodyGetAngularVel(body);
  dVector3 wb, lb, l;
  dBodyVectorFromWorld(body, w[0], w[1], w[2], wb);
  for (int i = 0; i < 3; ++i) lb[i] = mass.I[i * 4] * wb[0] + mass.I[i * 4 + 1] * wb[1] + mass.I[i * 4 + 2] * wb[2];
  dBodyVectorToWorld(body, lb[0], lb[1], lb[2], l);
  return {l[0], l[1], l[2]};
}

// The largest contact depth among the pairs ODE's broad phase offers that may touch.
struct DeepestContact {
  int maxContacts;
  double depth = 0.0;
  static void near(void* data, dGeomID a, dGeomID b) {
    auto& self = *static_cast<DeepestContact*>(data);
    const dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
    if ((!ba && !bb) || ba == bb || (ba && bb && dAreConnectedExcluding(ba, bb, dJointTypeContact))) return;
    std::vector<dContactGeom> contacts(static_cast<size_t>(self.maxContacts));
    const int n = dCollide(a, b, self.maxContacts, contacts.data(), sizeof(dContactGeom));
    for (int i = 0; i < n; ++i) self.depth = std::max(self.depth, static_cast<double>(contacts[static_cast<size_t>(i)].depth));
  }
};

}  // namespace

double WorldMeasures::Crossings::period() const { return count >= 3 ? 2.0 * (last - first) / (count - 1) : NaN; }

// The probe's quantity now: a component of the body's state, or its magnitude.
double WorldMeasures::reading(const Measure& m, dBodyID body) const {
  Vec3 v{0, 0, 0};
  switch (m.of) {
    case ProbeOf::Position: v = vec(dBodyGetPosition(body)); break;
    case ProbeOf::Velocity: v = vec(dBodyGetLinearVel(body)); break;
    case ProbeOf::Displacement: v = minus(vec(dBodyGetPosition(body)), startPosition_[static_cast<size_t>(m.body)]); break;
    case ProbeOf::AngularVelocity: v = vec(dBodyGetAngularVel(body)); break;
    case ProbeOf::AngularMomentum: v = spin(body); break;
    case ProbeOf::Energy: return last_.energy;
  }
  return m.axis == MAGNITUDE ? norm(v.data()) : v[static_cast<size_t>(m.axis)];
}

// One reading at `time` (s since the body appeared) into the probe's figure.
// A time between two steps (`at`, a crossing) is interpolated linearly
// between their readings, so the figure does not move by a step's share.
void WorldMeasures::Probe::take(const Measure& m, double reading, double time) {
  // A step's time is a sum of steps, a rounding off the bound a file names
  // (70 steps of 0.01 s end at 0.7000000000000001 s): a thousandth of the
  // smallest step keeps a step that lands on a bound inside the window.
  constexpr double SLACK = 1e-9;  // s
  const bool inWindow = time >= m.from - SLACK && time <= m.until + SLACK;
  switch (m.take) {
    case ProbeTake::At:
      if (std::isnan(m.at)) {
        figure = reading;  // the run's last state
      } else if (std::isnan(figure) && time >= m.at - SLACK) {
        // On a step (to rounding): its reading; past one: between it and the step before.
        figure = time <= m.at + SLACK || std::isnan(previous)
                     ? reading
                     : previous + (reading - previous) * (m.at - previousTime) / (time - previousTime);
      }
      break;
    case ProbeTake::Max:
      if (inWindow && !(figure >= reading)) figure = reading;
      break;
    case ProbeTake::Min:
      if (inWindow && !(figure <= reading)) figure = reading;
      break;
    case ProbeTake::FirstCrossing:
      if (inWindow && std::isnan(figure) && !std::isnan(previous) && previousTime >= m.from - SLACK &&
          (previous - m.value > 0) != (reading - m.value > 0))
        figure = previousTime + (time - previousTime) * (previous - m.value) / (previous - reading);
      break;
  }
  previous = reading;
  previousTime = time;
}

WorldMeasures::WorldMeasures(const World& world, dWorldID odeWorld, dSpaceID space, std::vector<dBodyID> bodies)
    : world_(world), odeWorld_(odeWorld), space_(space), bodies_(std::move(bodies)),
      appeared_(bodies_.size(), 0.0), startPosition_(bodies_.size()), startVelocity_(bodies_.size()),
      side_(bodies_.size(), NaN), tunnelled_(bodies_.size(), false),
      ballisticError_(world.measures.size(), 0.0), swings_(world.measures.size()), probes_(world.measures.size()),
      restingSince_(NaN), timeToRest_(NaN) {
  for (size_t i = 0; i < bodies_.size(); ++i)
    if (bodies_[i]) {
      startPosition_[i] = vec(dBodyGetPosition(bodies_[i]));
      startVelocity_[i] = vec(dBodyGetLinearVel(bodies_[i]));
    }
  // The centre angular momentum is taken about: the start's centre of mass.
  double mass = 0.0;
  for (size_t i = 0; i < bodies_.size(); ++i)
    if (bodies_[i] && !dBodyIsKinematic(bodies_[i])) {
      const double m = world.bodies[i].mass;
      for (int k = 0; k < 3; ++k) centre_[static_cast<size_t>(k)] += m * startPosition_[i][static_cast<size_t>(k)];
      mass += m;
    }
  if (mass > 0)
    for (double& c : centre_) c /= mass;
  start_ = last_ = totals();
  energyMin_ = energyMax_ = start_.energy;
  for (const Measure& m : world.measures) {
    if (m.kind == MeasureKind::Energy) energyScale_ = m.scale > 0 ? m.scale : std::abs(start_.energy);
    if (m.kind == MeasureKind::Momentum) {
      linearScale_ = m.scale > 0 ? m.scale : start_.linearScale;
      angularScale_ = m.angularScale > 0 ? m.angularScale : start_.angularScale;
    }
  }
  // A world at rest has no scale of its own: 1 in the measure's unit, and the metric says which.
  if (!(energyScale_ > 0)) energyScale_ = 1.0;
  if (!(linearScale_ > 0)) linearScale_ = 1.0;
  if (!(angularScale_ > 0)) angularScale_ = 1.0;
  if (has(world, MeasureKind::JointError)) watchJoints();
  afterStep(0.0);
}

Totals WorldMeasures::totals() const {
  Totals t;
  for (size_t i = 0; i < bodies_.size(); ++i) {
    const dBodyID body = bodies_[i];
    if (!body || dBodyIsKinematic(body)) continue;  // a kinematic body is moved from outside
    const double m = world_.bodies[i].mass;
    t.energy += mechanicalEnergy(body, odeWorld_);
    const dReal* v = dBodyGetLinearVel(body);
    const Vec3 r = minus(vec(dBodyGetPosition(body)), centre_);
    const Vec3 s = spin(body);
    const Vec3 mv{m * v[0], m * v[1], m * v[2]};
    const Vec3 orbit = cross(r.data(), mv.data());
    for (size_t k = 0; k < 3; ++k) {
      t.linear[k] += mv[k];
      t.angular[k] += orbit[k] + s[k];
    }
    t.linearScale += m * norm(v);
    t.angularScale += norm(r.data()) * m * norm(v) + norm(s.data());
  }
  return t;
}

void WorldMeasures::beforeEvent() { beforeEvent_ = totals(); }

void WorldMeasures::afterEvent(int body, dBodyID added, double time) {
  if (added) {
    bodies_[static_cast<size_t>(body)] = added;
    appeared_[static_cast<size_t>(body)] = time;
    startPosition_[static_cast<size_t>(body)] = vec(dBodyGetPosition(added));
    startVelocity_[static_cast<size_t>(body)] = vec(dBodyGetLinearVel(added));
  }
  const Totals after = totals();
  start_.energy += after.energy - beforeEvent_.energy;
  for (size_t k = 0; k < 3; ++k) {
    start_.linear[k] += after.linear[k] - beforeEvent_.linear[k];
    start_.angular[k] += after.angular[k] - beforeEvent_.angular[k];
  }
}

void WorldMeasures::afterStep(double time) {
  time_ = time;
  last_ = totals();
  energyMin_ = std::min(energyMin_, last_.energy);
  energyMax_ = std::max(energyMax_, last_.energy);
  // Against the start plus what events brought so far (test2's figure when there are none).
  energyDeviation_ = std::max(energyDeviation_, std::abs(last_.energy - start_.energy) / energyScale_);
  const Vec3 dp = minus(last_.linear, start_.linear), dl = minus(last_.angular, start_.angular);
  linearDrift_ = std::max(linearDrift_, norm(dp.data()) / linearScale_);
  angularDrift_ = std::max(angularDrift_, norm(dl.data()) / angularScale_);
  if (!joints_.empty()) jointErrors();
  if (has(world_, MeasureKind::Penetration)) penetration_ = std::max(penetration_, deepestContact());
  if (has(world_, MeasureKind::Tunnelling)) tunnelling();
  dVector3 g;
  dWorldGetGravity(odeWorld_, g);
  bool resting = true;
  for (size_t i = 0; i < world_.measures.size(); ++i) {
    const Measure& m = world_.measures[i];
    if (m.kind == MeasureKind::Probe && m.of == ProbeOf::Energy) {
      probes_[i].take(m, last_.energy, time);
      continue;
    }
    const dBodyID body = m.body >= 0 ? bodies_[static_cast<size_t>(m.body)] : nullptr;
    if (!body) continue;
    if (m.kind == MeasureKind::Ballistic) {
      const double t = time - appeared_[static_cast<size_t>(m.body)];
      if (time > m.until) continue;
      const double gravity = dBodyGetGravityMode(body) ? 1.0 : 0.0;
      const dReal* p = dBodyGetPosition(body);
      const Vec3& p0 = startPosition_[static_cast<size_t>(m.body)];
      const Vec3& v0 = startVelocity_[static_cast<size_t>(m.body)];
      double error = 0.0;
      for (size_t k = 0; k < 3; ++k) {
        const double d = p[k] - (p0[k] + v0[k] * t + 0.5 * gravity * g[k] * t * t);
        error += d * d;
      }
      ballisticError_[i] = std::max(ballisticError_[i], std::sqrt(error));
    } else if (m.kind == MeasureKind::Probe) {
      probes_[i].take(m, reading(m, body), time - appeared_[static_cast<size_t>(m.body)]);
    } else if (m.kind == MeasureKind::Period) {
      Crossings& c = swings_[i];
      const double value = dBodyGetPosition(body)[m.axis] - m.about;
      if (c.started && (c.previousValue > 0) != (value > 0)) {
        const double at = c.previousTime + (time - c.previousTime) * c.previousValue / (c.previousValue - value);
        if (c.count++ == 0) c.first = at;
        c.last = at;
      }
      c.started = true;
      c.previousValue = value;
      c.previousTime = time;
    }
  }
  for (const Measure& m : world_.measures) {
    if (m.kind != MeasureKind::Rest) continue;
    for (const dBodyID body : bodies_)
      if (body && (norm(dBodyGetLinearVel(body)) >= m.speed || norm(dBodyGetAngularVel(body)) >= m.angularSpeed))
        resting = false;
    if (!resting) {
      restingSince_ = NaN;
    } else {
      if (std::isnan(restingSince_)) restingSince_ = time;
      if (std::isnan(timeToRest_) && time - restingSince_ >= m.hold) timeToRest_ = restingSince_;
    }
  }
}

double WorldMeasures::deepestContact() {
  DeepestContact deepest{world_.settings.maxContacts};
  dSpaceCollide(space_, &deepest, &DeepestContact::near);
  return deepest.depth;
}

void WorldMeasures::addMetrics(Metrics& m) const {
  for (size_t i = 0; i < world_.measures.size(); ++i) {
    const Measure& measure = world_.measures[i];
    switch (measure.kind) {
      case MeasureKind::Energy:
        m.set("energy_start_J", start_.energy);
        m.set("energy_min_J", energyMin_);
        m.set("energy_max_J", energyMax_);
        m.set("energy_last_J", last_.energy);
        m.set("energy_scale_J", energyScale_);
        m.set("energy_max_deviation", energyDeviation_);
        m.set("energy_drift", (last_.energy - start_.energy) / energyScale_);
        // Over the measure's scale, as the other energy figures: the largest
        // energy is 0 in a world at rest without gravity (0 / 0) and below 0
        // in a world under y = 0, where dividing by it gave no figure or a
        // negative one.
        m.set("energy_rel_variation", (energyMax_ - energyMin_) / energyScale_);
        break;
      case MeasureKind::Momentum:
        m.set("linear_momentum_drift", linearDrift_);
        m.set("angular_momentum_drift", angularDrift_);
        m.set("linear_momentum_scale", linearScale_);
        m.set("angular_momentum_scale", angularScale_);
        break;
      case MeasureKind::JointError:
        m.set("joint_error_max_m", jointError_);
        m.set("joint_axis_error_max_rad", axisError_);
        break;
      case MeasureKind::Penetration: m.set("penetration_max_m", penetration_); break;
      case MeasureKind::Tunnelling:
        m.set("tunnelled_bodies", static_cast<double>(std::count(tunnelled_.begin(), tunnelled_.end(), true)));
        m.set("tunnelling_crossings", crossings_);
        break;
      case MeasureKind::Ballistic: m.set(measure.name + "_error_max_m", ballisticError_[i]); break;
      case MeasureKind::Period:
        // Not measured before a whole period (three crossings).
        m.set(measure.name + "_period_s", swings_[i].period(), swings_[i].count >= 3);
        m.set(measure.name + "_period_expected_s", measure.expected);
        m.set(measure.name + "_period_error", (swings_[i].period() - measure.expected) / measure.expected,
              swings_[i].count >= 3);
        break;
      case MeasureKind::Rest:  // not measured until the bodies have rested for the measure's hold
        m.set("time_to_rest_s", timeToRest_, !std::isnan(timeToRest_));
        break;
      case MeasureKind::Probe: {
        // Not measured when never read (a crossing that did not happen).
        const double value = probes_[i].figure;
        const bool read = !std::isnan(value);
        m.set(measure.name + "_value", value, read);
        if (std::isnan(measure.expect)) break;
        const double tolerance =
            std::isnan(measure.tolerance) ? measure.relativeTolerance * std::abs(measure.expect) : measure.tolerance;
        m.set(measure.name + "_expected", measure.expect);
        m.set(measure.name + "_error", value - measure.expect, read);
        m.set(measure.name + "_tolerance", tolerance);
        m.set(measure.name + "_within", read && std::abs(value - measure.expect) <= tolerance ? 1.0 : 0.0);
        break;
      }
    }
  }
}

bool WorldMeasures::plotValue(double& value) const {
  if (!has(world_, MeasureKind::Energy)) return false;
  value = last_.energy;
  return true;
}

void WorldMeasures::addHudLines(std::vector<std::string>& lines) const {
  for (size_t i = 0; i < world_.measures.size(); ++i) {
    const Measure& measure = world_.measures[i];
    std::ostringstream s;
    s << std::setprecision(4);
    switch (measure.kind) {
      case MeasureKind::Energy:
        s << "energy " << last_.energy << " J (start " << start_.energy << " J)   drift "
          << 100.0 * (last_.energy - start_.energy) / energyScale_ << " %   largest "
          << 100.0 * energyDeviation_ << " %";
        break;
      case MeasureKind::Momentum:
        s << "momentum drift: linear " << 100.0 * linearDrift_ << " %   angular " << 100.0 * angularDrift_ << " % (largest)";
        break;
      case MeasureKind::JointError:
        s << "joint error: anchors " << jointError_ << " m   axes " << axisError_ << " rad (largest)";
        break;
      case MeasureKind::Penetration: s << "deepest penetration " << penetration_ << " m"; break;
      case MeasureKind::Tunnelling:
        s << "through geom " << measure.geom << ": " << std::count(tunnelled_.begin(), tunnelled_.end(), true)
          << " bodies (" << crossings_ << " crossings)";
        break;
      case MeasureKind::Ballistic:
        s << measure.name << ": off the ballistic arc by " << ballisticError_[i] << " m at most";
        break;
      case MeasureKind::Period:
        s << measure.name << ": period " << swings_[i].period() << " s (expected " << measure.expected << " s)";
        break;
      case MeasureKind::Probe:
        s << measure.name << " " << probes_[i].figure;
        if (!std::isnan(measure.expect))
          s << " (expected " << measure.expect << " +- "
            << (std::isnan(measure.tolerance) ? measure.relativeTolerance * std::abs(measure.expect) : measure.tolerance) << ")";
        break;
      case MeasureKind::Rest:
        s << "at rest " << (std::isnan(timeToRest_) ? std::string("not yet") : "from " + std::to_string(timeToRest_) + " s");
        break;
    }
    lines.push_back(s.str());
  }
}

}  // namespace odelab::world
