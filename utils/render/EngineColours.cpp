#include "EngineColours.h"

namespace odelab {

namespace {

struct Entry {
  const char* engine;
  EngineColour colour;
};
// Every pair at least 100 apart in RGB (checks/unit/test_engine_colours.cpp),
// so a curve or an outline is told from its neighbour at a glance, and each
// bright enough to read on the plot's dark box and the view's sky. ODE's
// blue is its plot curve and, in a view of its own, its world bodies' edges.
const Entry ENGINE_COLOURS[] = {
    {"ode", {70, 120, 255, "blue"}},      {"bullet", {255, 140, 30, "orange"}}, {"mujoco", {120, 255, 90, "green"}},
    {"havok", {255, 60, 200, "magenta"}}, {"jolt", {250, 240, 60, "yellow"}},   {"rapier", {40, 220, 255, "cyan"}},
    {"physx", {230, 40, 40, "red"}},
};
const EngineColour OTHER_COLOUR = {240, 240, 240, "white"};
const EngineColour GHOST_COLOUR = {45, 45, 45, "dark grey"};

const Entry* find(const std::string& engine) {
  for (const Entry& e : ENGINE_COLOURS)
    if (engine == e.engine) return &e;
  return nullptr;
}

}  // namespace

const EngineColour& engineColour(const std::string& engine) {
  const Entry* e = find(engine);
  return e ? e->colour : OTHER_COLOUR;
}

const EngineColour& ghostColour() { return GHOST_COLOUR; }

bool hasOwnColour(const std::string& engine) { return find(engine) != nullptr; }

std::string colourLegend(const std::vector<std::string>& engines) {
  std::string text;
  for (const std::string& engine : engines) text += (text.empty() ? "" : ", ") + engine + " " + engineColour(engine).name;
  return text;
}

}  // namespace odelab
