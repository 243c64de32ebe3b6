#pragma once

// The world a program built in ODE, described as data (WorldDescription.h):
// what --export-world writes and what an engine adapter is given to build.

#include <ode/ode.h>

#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "AbstractObject.h"
#include "WorldDescription.h"
#include "WorldSettings.h"

namespace odelab::world {

// The scene's near-callback surface for a pair (AbstractWindow::setContactSurface).
using SurfaceOf = std::function<void(dGeomID, dGeomID, dSurfaceParameters&)>;

Settings settingsOf(dWorldID world, const WorldSettings& settings, int maxContacts, const char* spaceName);
Surface surfaceOf(const dSurfaceParameters& surface);
dSurfaceParameters odeSurface(const Surface& surface);

// Which ODE body and geom each index of a description stands for, so that a
// description can grow as the scene adds objects and engine states can be
// written back.
struct OdeIndex {
  std::vector<dBodyID> bodies;
  std::vector<dGeomID> geoms;
  std::vector<dJointID> joints;
  std::map<dBodyID, int> bodyIndex;
  std::map<dGeomID, int> geomIndex;
};

// Appends to `world` every body, geom and joint of `objects` not yet in
// `index` (all of them the first time), in the order the objects were
// made, with the surfaces of the new pairs. Returns nothing new as zero-sized
// additions. The world's settings are read (set them first: a ball or fixed
// joint still at the world's ERP and CFM is described as taking them), not touched.
void describeNewObjects(const std::vector<std::unique_ptr<AbstractObject>>& objects, const SurfaceOf& surfaceOf,
                        World& world, OdeIndex& index);
// Every pair's surface again (after mu or a bounce changed).
void describeSurfaces(const SurfaceOf& surfaceOf, World& world, const OdeIndex& index);

// A body's state in the description's terms.
Body bodyOf(dBodyID body);

}  // namespace odelab::world
