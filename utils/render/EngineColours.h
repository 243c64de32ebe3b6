#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace odelab {

// Each engine's colour, the same in every run and everywhere it is shown
// (a compare view's label, the merged view's outlines, a world body's
// edges, the live plot's curve, the legends), keyed by the engine's name and
// not by its place in --compare. Pure data, no drawing, so the checks read
// the very table the window draws with.
struct EngineColour {
  std::uint8_t r, g, b;
  const char* name;  // in words, for the legends: "orange"
};

// The colour of `engine` ("ode", "bullet", ...); an engine the table does
// not know (a later one) gets white until it is given its own.
const EngineColour& engineColour(const std::string& engine);
// Whether the table has `engine` (false: it is drawn in the fallback white).
bool hasOwnColour(const std::string& engine);

// The analytic ghost's colour (GhostDraw.h): a neutral dark grey, no
// engine's (at least as far from each engine's colour and the fallback white
// as the engines are from one another), dark on the sky and the ground alike.
const EngineColour& ghostColour();

// The plot's legend: "ode blue, bullet orange, ..." for `engines` in order.
std::string colourLegend(const std::vector<std::string>& engines);

}  // namespace odelab
