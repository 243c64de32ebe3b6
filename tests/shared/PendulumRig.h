#pragma once

// The pendulum of test2 (thesis 5.3) and test8 (thesis 5.9): a rod and a
// sphere merged with attach() into one composite body, hinged to the static
// world at [0, 7, 0] about the z axis, starting horizontal (pi/2 from the
// vertical). Header-only so both programs share it without a CMake change.

#include <ode/ode.h>

#include <cmath>

#include "AbstractWindow.h"
#include "Box.h"
#include "Plane.h"
#include "Sphere.h"
#include "SceneConstants.h"

namespace odelab::pendulum {

// The rig's dimensions and masses live in SceneConstants.h (shared with the
// peer engines in peers/).
using scene::test2::ANCHOR_HEIGHT;
using scene::test2::BOB_DISTANCE;
using scene::test2::BOB_MASS;
using scene::test2::BOB_RADIUS;
using scene::test2::ROD_LENGTH;
using scene::test2::ROD_MASS;
using scene::test2::ROD_THICKNESS;
using scene::test2::START_DEFLECTION;
constexpr double ANCHOR_MARKER_RADIUS = 0.08;  // drawn at the hinge; collides with nothing

// The rig's shape: the thesis gives none of it (SceneConstants.h marks the
// values "proposed"); test2 can change it to show what the shape does to
// the energy it reports. The bob's centre is at the rod's far end plus its
// radius, as in the default rig (3.0 + 0.3).
struct PendulumShape {
  double rodLength = ROD_LENGTH;
  double rodThickness = ROD_THICKNESS;
  double rodMass = ROD_MASS;
  double bobRadius = BOB_RADIUS;
  double bobDistance() const { return rodLength + bobRadius; }
};

// Mass properties worked out by hand from the constants above (not read back
// from ODE), so a period that matches them also vouches for attach().
struct MassProperties {
  double mass;              // kg
  double centreDistance;    // anchor to the composite centre of mass, m
  double inertiaAboutAxis;  // about the hinge axis (z through the anchor), kg m^2
};

inline MassProperties massProperties(double bobMass, const PendulumShape& shape = {}) {
  const double rodCentre = shape.rodLength / 2, rodMass = shape.rodMass, bobDistance = shape.bobDistance();
  const double rod = rodMass * (shape.rodLength * shape.rodLength + shape.rodThickness * shape.rodThickness) / 12.0 +
                     rodMass * rodCentre * rodCentre;
  const double bob = 0.4 * bobMass * shape.bobRadius * shape.bobRadius + bobMass * bobDistance * bobDistance;
  const double mass = rodMass + bobMass;
  return {mass, (rodMass * rodCentre + bobMass * bobDistance) / mass, rod + bob};
}

// Complete elliptic integral of the first kind K(k), by the arithmetic-
// geometric mean: K(k) = pi / (2 AGM(1, sqrt(1 - k^2))).
inline double ellipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  while (std::fabs(a - b) > 1e-15 * a) {
    const double mean = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = mean;
  }
  return M_PI / (2.0 * a);
}

// Exact period of a physical pendulum of amplitude theta0:
// T = 4 sqrt(I / (m g d)) K(sin(theta0 / 2)).
inline double exactPeriod(const MassProperties& p, double gravity, double amplitude) {
  return 4.0 * std::sqrt(p.inertiaAboutAxis / (p.mass * gravity * p.centreDistance)) *
         ellipticK(std::sin(amplitude / 2));
}

// Kinetic energy of a body, rotation included: 0.5 m v^2 + 0.5 w^T I w, with
// w taken into the body frame where ODE keeps I (about the centre of mass,
// which attach() puts at the body's origin).
inline double massOf(dBodyID body) {
  dMass m;
  dBodyGetMass(body, &m);
  return m.mass;
}
inline double translationalKineticEnergy(dBodyID body) {
  const dReal* v = dBodyGetLinearVel(body);
  return 0.5 * massOf(body) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}
inline double rotationalKineticEnergy(dBodyID body) {
  dMass m;
  dBodyGetMass(body, &m);
  dVector3 w;
  dMultiply1_331(w, dBodyGetRotation(body), dBodyGetAngularVel(body));  // R^T w
  double rotational = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rotational += w[i] * m.I[i * 4 + j] * w[j];
  return 0.5 * rotational;
}
inline double kineticEnergy(dBodyID body) { return translationalKineticEnergy(body) + rotationalKineticEnergy(body); }

// Base of the two pendulum scenes: builds the rig and reads its state.
class PendulumScene : public AbstractWindow {
 public:
  using AbstractWindow::AbstractWindow;

  SceneBounds bounds() const override { return {{0.0, 4.0, 0.0}, 8.0}; }

 protected:
  // Ground plane, rod and bob placed horizontally along +x, merged into the
  // rod's body, hinged to the world. Returns the composite body.
  dBodyID buildPendulum(double bobMass) {
    Plane& ground = add<Plane>(space());
    ground.color = Color{0.55f, 0.6f, 0.55f};
    Box& rod = add<Box>(world(), space(), shape_.rodLength, shape_.rodThickness, shape_.rodThickness, shape_.rodMass);
    rod.setPosition(shape_.rodLength / 2, ANCHOR_HEIGHT, 0.0);
    rod.color = Color{0.75f, 0.7f, 0.55f};
    Sphere& bob = add<Sphere>(world(), space(), shape_.bobRadius, bobMass);
    bob.setPosition(shape_.bobDistance(), ANCHOR_HEIGHT, 0.0);
    bob.color = Color{0.8f, 0.3f, 0.25f};
    bob.attach(rod);  // the thesis's composite object: one body, two geoms
    addAnchorMarker();

    body_ = rod.getBody();
    bobGeom_ = bob.getGeom();
    hinge_ = dJointCreateHinge(world(), 0);
    dJointAttach(hinge_, body_, 0);  // 0: the static world
    dJointSetHingeAnchor(hinge_, 0.0, ANCHOR_HEIGHT, 0.0);
    dJointSetHingeAxis(hinge_, 0.0, 0.0, 1.0);
    return body_;
  }

  dBodyID pendulumBody() const { return body_; }
  PendulumShape shape_;

  // Height of the bob's lowest point above the ground (negative: through it).
  double bobClearance() const { return dGeomGetPosition(bobGeom_)[1] - shape_.bobRadius; }

  // Anchor to the composite centre of mass (the body's position after attach).
  double anchorToCentreOfMass() const {
    const dReal* p = dBodyGetPosition(body_);
    const double dy = p[1] - ANCHOR_HEIGHT;
    return std::sqrt(p[0] * p[0] + dy * dy + p[2] * p[2]);
  }

  // Deflection of the centre of mass from straight down, radians; positive
  // towards +x (the start is +pi/2).
  double deflection() const {
    const dReal* p = dBodyGetPosition(body_);
    return std::atan2(p[0], ANCHOR_HEIGHT - p[1]);
  }

  // Gravitational potential energy m g y of the centre of mass, y from the
  // ground (the thesis's convention).
  double potentialEnergy() const {
    dMass m;
    dBodyGetMass(body_, &m);
    return m.mass * settings().gravity * dBodyGetPosition(body_)[1];
  }

  void initialCamera(Camera& camera) const override { camera.lookAt({0.5, 6.2, 9.5}, {0.8, 5.4, 0.0}); }

 private:
  // A small static sphere showing where the hinge is. Its category and
  // collide bits are 0, so dSpaceCollide never pairs it with anything.
  void addAnchorMarker() {
    Sphere& marker = add<Sphere>(world(), space(), ANCHOR_MARKER_RADIUS, 1.0);
    marker.setAsFixedGeom();
    marker.setPosition(0.0, ANCHOR_HEIGHT, 0.0);
    marker.color = Color{0.3f, 0.3f, 0.35f};
    dGeomSetCategoryBits(marker.getGeom(), 0);
    dGeomSetCollideBits(marker.getGeom(), 0);
  }

  dBodyID body_ = nullptr;
  dJointID hinge_ = nullptr;
  dGeomID bobGeom_ = nullptr;
};

}  // namespace odelab::pendulum
