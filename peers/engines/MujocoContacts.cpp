#include "MujocoContacts.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace odelab::engines::mujoco {

namespace {

// No MuJoCo friction coefficient is infinite: a contact that never slides
// (ODE's mu = dInfinity) gets 100, a friction cone of 89.4 degrees (sliding
// only once the tangential force is 100 times the normal).
constexpr double NO_SLIP_FRICTION = 100.0;

// A number as a note says it: short.
std::string say(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The damping b of a linear spring-damper of stiffness k that gives back e
// of the impact speed: damping ratio z = -ln e / sqrt(pi^2 + ln^2 e), b = 2 z sqrt(k).
double bounceDamping(double e) {
  if (e >= 1.0) return 0.0;
  const double l = std::log(e);
  return 2.0 * (-l / std::sqrt(M_PI * M_PI + l * l)) * std::sqrt(BOUNCE_STIFFNESS);
}

}  // namespace

std::string num(double value) {
  std::ostringstream s;
  s.precision(17);
  s << value;
  return s.str();
}

bool bounces(const world::Surface& surface) { return surface.bounce && surface.restitution > 0.0; }

std::string pairFriction(double mu) { return num(mu) + ' ' + num(mu) + " 0.005 0.0001 0.0001"; }
std::string geomFriction(double mu) { return num(mu) + " 0.005 0.0001"; }

ContactParams contactOf(const world::Surface& surface, world::EngineSetting setting, double step,
                        SurfaceLosses& losses) {
  ContactParams c;
  if (std::isinf(surface.mu)) {
    c.mu = NO_SLIP_FRICTION;
    losses.infiniteFriction = true;
  } else if (surface.mu <= 0.0) {
    c.condim = 1;  // MuJoCo's frictionless contact
  } else {
    c.mu = surface.mu;
    if (!surface.approx1) losses.forceBounds.insert(surface.mu);
  }
  const bool best = setting == world::EngineSetting::Best;
  if (best) {
    c.solref = num(BEST_TIME_CONSTANT_STEPS * step) + " 1";
    c.solimp = BEST_SOLIMP;
  }
  if (bounces(surface)) {
    losses.restitutions.insert(surface.restitution);
    if (best) {
      c.solref = num(-BOUNCE_STIFFNESS) + ' ' + num(-bounceDamping(surface.restitution));
      c.solimp.clear();  // MuJoCo's own impedance, with which the spring was measured
      if (surface.bounceVelocity > 0.0) losses.bounceVelocities.insert(surface.bounceVelocity);
    }
  }
  losses.softness = losses.softness || surface.softErp || surface.softCfm;
  return c;
}

namespace {

// "0.5" or "0.02 to 1 (49 surfaces)".
std::string span(const std::set<double>& values, const char* unit = "", bool count = true) {
  if (values.size() == 1) return say(*values.begin()) + unit;
  return say(*values.begin()) + " to " + say(*values.rbegin()) + unit +
         (count ? " (" + std::to_string(values.size()) + " surfaces)" : std::string());
}

}  // namespace

std::vector<std::string> notesOf(const SurfaceLosses& losses, world::EngineSetting setting) {
  std::vector<std::string> notes;
  if (losses.infiniteFriction)
    notes.push_back("infinite friction (mu = infinity) became friction " + say(NO_SLIP_FRICTION) +
                    ", a friction cone of 89.4 degrees, for contacts that never slide: MuJoCo's friction is a "
                    "finite coefficient");
  if (!losses.forceBounds.empty())
    notes.push_back("friction mu = " + span(losses.forceBounds) +
                    " without friction_pyramid: ODE takes it as a friction force bound in newtons, MuJoCo as a "
                    "Coulomb coefficient (the bound grows with the normal force)");
  if (!losses.restitutions.empty()) {
    if (setting == world::EngineSetting::Best) {
      std::set<double> dampings;
      for (const double e : losses.restitutions) dampings.insert(bounceDamping(e));
      notes.push_back("restitution " + span(losses.restitutions) + " became a spring-damper contact, solref \"" +
                      say(-BOUNCE_STIFFNESS) + " -b\" with b = " + span(dampings, "", false) +
                      " (MuJoCo has no restitution coefficient; b is the damping with which a free linear "
                      "spring-damper gives back that fraction of the impact speed): a body sinks into the surface "
                      "while it bounces and when it rests");
    } else {
      notes.push_back("restitution " + span(losses.restitutions) +
                      " is lost: MuJoCo has no restitution coefficient and its default contact (solref 0.02 1, "
                      "critically damped) does not bounce; --engine-setting best approximates the bounce with a "
                      "spring contact");
    }
  }
  if (!losses.bounceVelocities.empty())
    notes.push_back("the bounce threshold bounce_velocity " + span(losses.bounceVelocities, " m/s") +
                    " is not applied: MuJoCo's spring contact has no threshold");
  if (losses.softness)
    notes.push_back("a surface's own ERP or CFM (soft_erp, soft_cfm) has no MuJoCo equivalent: the contact is "
                    "softened by MuJoCo's solref and solimp instead");
  return notes;
}

}  // namespace odelab::engines::mujoco
