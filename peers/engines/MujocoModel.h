#pragma once

// A world description as MJCF, the only way MuJoCo 2.2 builds a model: the
// bodies in the kinematic tree planned by MujocoLayout, their geoms and
// exact masses, the joints that close loops as equality constraints, the
// contact surfaces as geom friction and <pair> elements, and the settings.
// What MJCF cannot say exactly is returned as translation notes.

#include <string>
#include <vector>

#include "MujocoLayout.h"
#include "world/Engine.h"

namespace odelab::engines::mujoco {

// The body and geom names in the MJCF, by their index in the world.
std::string bodyName(int body);
std::string geomName(int geom);

struct ModelRequest {
  const world::World& world;
  const Layout& layout;
  const std::vector<JointFrames>& frames;
  world::EngineSetting setting;
  int nconmax = 100;  // MuJoCo 2.2's buffers are fixed when the data is made
  int njmax = 500;
};

struct ModelText {
  std::string xml;
  std::vector<std::string> notes;
  bool rk4 = false;  // the integrator chosen (Best)
};

// Throws world::EngineError for what MuJoCo cannot hold at all.
ModelText writeModel(const ModelRequest& request);

// A first guess at the room the contacts and constraint rows need; the
// engine doubles it whenever MuJoCo says a buffer was full.
void initialSizes(const world::World& world, const Layout& layout, int& nconmax, int& njmax);

}  // namespace odelab::engines::mujoco
