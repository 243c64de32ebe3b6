#pragma once

#include <ode/ode.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace odelab {

enum class Shape { Box, Sphere, Plane, Capsule, Cylinder };

struct Color {
  float r, g, b;
};

// One ODE geom and (optionally) one body, plus what the renderer needs to
// draw it. The physics side never draws: the renderer reads shape(),
// dimensions and the geom's pose.
class AbstractObject {
 public:
  AbstractObject(const AbstractObject&) = delete;
  AbstractObject& operator=(const AbstractObject&) = delete;
  virtual ~AbstractObject();

  Shape shape() const { return shape_; }
  dGeomID getGeom() const { return geom_; }
  // The body this geom rides on: its own, another object's after attach(),
  // or 0 for a fixed geom.
  dBodyID getBody() const { return dGeomGetBody(geom_); }
  bool isFixed() const { return getBody() == nullptr; }
  // Active bodies draw in colour, disabled ones grey; fixed geoms count as active.
  bool isEnabled() const;

  // Turns this object into static geometry by destroying its body.
  void setAsFixedGeom();

  // Merges this object's mass into other's body and re-seats this geom on it
  // (the thesis's chapter 8): both masses are moved to world coordinates,
  // summed and checked; the composite body is moved to the summed centre of
  // mass and every geom on it keeps its world pose through its offset; this
  // object's own body is destroyed. Returns false (and changes nothing) when
  // either object has no body or the summed mass fails dMassCheck.
  bool attach(AbstractObject& other);

  // User data, stored as the geom's data (dGeomSetData) so the near callback
  // can read it from the geom alone. The bytes are copied.
  void setData(const void* data, std::size_t size);
  void* getData() const { return dGeomGetData(geom_); }
  template <class T>
  static const T* dataOf(dGeomID geom) {
    return static_cast<const T*>(dGeomGetData(geom));
  }

  void setPosition(double x, double y, double z);
  void setLinearVelocity(double x, double y, double z);
  const dReal* getPosition() const { return dGeomGetPosition(geom_); }
  double mass() const;  // of the body it rides on; 0 if fixed

  Color color{0.8f, 0.8f, 0.8f};
  bool visible = true;
  // Drawn with its edges in the engine's colour (a world file's bodies: boxes
  // stacked in one colour would otherwise read as one column).
  bool edged = false;

  // Counts every change of which bodies exist or which body a geom rides on
  // (an object made or destroyed, fixed or attached), so that a per-step
  // cache of bodies (BodyStateWatch) knows when to look again.
  static std::uint64_t bodyChanges() { return bodyChanges_; }

 protected:
  AbstractObject(Shape shape, dGeomID geom, dBodyID body);

 private:
  Shape shape_;
  dGeomID geom_;
  dBodyID ownBody_;  // the body this object created and still owns, or 0
  std::vector<unsigned char> data_;
  inline static std::uint64_t bodyChanges_ = 0;
};

}  // namespace odelab
