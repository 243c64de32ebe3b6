#include "CompareViews.h"

#include <algorithm>
#include <cmath>

#include "../Box.h"
#include "../Cylindrical.h"
#include "../Sphere.h"
#include "EngineColours.h"
#include "WindowLayout.h"

namespace odelab {

namespace {

const int MARGIN = 6;  // pixels between a view's edge and its label
const int LABEL_BOX_ALPHA = 120;
const int CIRCLE_SEGMENTS = 24;
// Merged, a body is outlined only where it is this far from ODE's body of
// the same index (in the world every engine shares): where they agree there
// is nothing to draw, and where one drifts, it shows.
const double APART_METRES = 0.005;
const double APART_DEGREES = 1.0;

// See-through, so that ODE's solid bodies show under where the others agree.
const std::uint8_t OUTLINE_ALPHA = 110;
// A body's own edges are drawn on its faces, so they may be nearly opaque.
const std::uint8_t EDGE_ALPHA = 200;

// The engine's colour (EngineColours: one table for every view, curve and legend).
Rgba colourOf(const std::string& engine, std::uint8_t alpha) {
  const EngineColour& c = engineColour(engine);
  return {c.r, c.g, c.b, alpha};
}

// `line` without a closing aside: "   (start 29.567 J)", the same for every
// engine and in ODE's HUD line, or "   [4 notes]", which --list-engines and
// the exit table give in full.
std::string withoutAside(std::string line) {
  if (line.empty() || (line.back() != ')' && line.back() != ']')) return line;
  const size_t aside = line.rfind(line.back() == ')' ? "   (" : "   [");
  if (aside != std::string::npos) line.erase(aside);
  return line;
}

// The grid for `count` views: columns, rows.
void gridFor(size_t count, int& columns, int& rows) {
  columns = count <= 1 ? 1 : count <= 4 ? 2 : 3;
  rows = static_cast<int>((count + static_cast<size_t>(columns) - 1) / static_cast<size_t>(columns));
  if (count == 2) rows = 1;
}

// A geom's point at `local` (its own frame) in the world.
glm::vec3 at(dGeomID geom, const glm::vec3& local) {
  dVector3 world;
  const dReal* p = dGeomGetPosition(geom);
  const dReal* r = dGeomGetRotation(geom);
  for (int row = 0; row < 3; ++row)
    world[row] = p[row] + r[row * 4] * local.x + r[row * 4 + 1] * local.y + r[row * 4 + 2] * local.z;
  return {static_cast<float>(world[0]), static_cast<float>(world[1]), static_cast<float>(world[2])};
}

// A circle of `radius` about the geom's `axis` (0, 1, 2) at `offset` along it.
void circle(VertexList& list, dGeomID geom, int axis, float radius, float offset, Rgba color) {
  const float step = 2.0f * 3.14159265f / CIRCLE_SEGMENTS;
  auto point = [&](int i) {
    glm::vec3 local(0.0f);
    local[(axis + 1) % 3] = radius * std::cos(step * static_cast<float>(i));
    local[(axis + 2) % 3] = radius * std::sin(step * static_cast<float>(i));
    local[axis] = offset;
    return at(geom, local);
  };
  for (int i = 0; i < CIRCLE_SEGMENTS; ++i) list.line(point(i), point(i + 1), color);
}

// Whether two geoms' poses differ by more than APART_METRES or APART_DEGREES.
bool apart(dGeomID a, dGeomID b) {
  const dReal* p = dGeomGetPosition(a);
  const dReal* q = dGeomGetPosition(b);
  const double distance = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                    (p[2] - q[2]) * (p[2] - q[2]));
  if (distance > APART_METRES) return true;
  // The angle between them from the trace of Ra^T Rb (ODE's 3x4 rows).
  const dReal* r = dGeomGetRotation(a);
  const dReal* t = dGeomGetRotation(b);
  double trace = 0.0;
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 3; ++column) trace += r[row * 4 + column] * t[row * 4 + column];
  const double angle = std::acos(std::clamp((trace - 1.0) / 2.0, -1.0, 1.0)) * 180.0 / 3.14159265358979;
  return angle > APART_DEGREES;
}

void outline(VertexList& list, const AbstractObject& object, Rgba color) {
  const dGeomID geom = object.getGeom();
  switch (object.shape()) {
    case Shape::Box: {
      dVector3 sides;
      static_cast<const Box&>(object).sides(sides);
      const glm::vec3 half(sides[0] / 2, sides[1] / 2, sides[2] / 2);
      auto corner = [&](int i) {
        return at(geom, {i & 1 ? half.x : -half.x, i & 2 ? half.y : -half.y, i & 4 ? half.z : -half.z});
      };
      // The 12 edges: corners that differ in one bit.
      for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1)
          if (!(i & bit)) list.line(corner(i), corner(i | bit), color);
      break;
    }
    case Shape::Sphere: {
      const float radius = static_cast<float>(static_cast<const Sphere&>(object).radius());
      for (int axis = 0; axis < 3; ++axis) circle(list, geom, axis, radius, 0.0f, color);
      break;
    }
    case Shape::Capsule:
    case Shape::Cylinder: {
      double radius, length;
      static_cast<const Cylindrical&>(object).dimensions(radius, length);
      const float r = static_cast<float>(radius), half = static_cast<float>(length / 2);
      for (const float end : {-half, half}) circle(list, geom, 2, r, end, color);
      for (int i = 0; i < 4; ++i) {
        const float angle = 3.14159265f / 2 * static_cast<float>(i);
        const float x = r * std::cos(angle), y = r * std::sin(angle);
        list.line(at(geom, {x, y, -half}), at(geom, {x, y, half}), color);
      }
      break;
    }
    case Shape::Plane:
      break;  // the ground is every engine's
  }
}

}  // namespace

CompareViews::CompareViews(const std::string& shaderDir) : program_(shaderDir) {}

void CompareViews::setShown(size_t lane, bool shown) {
  if (lane == 0) return;
  if (hidden_.size() <= lane) hidden_.resize(lane + 1, false);
  hidden_[lane] = !shown;
}

std::vector<CompareViews::Rect> CompareViews::layout(const CompareLanes& lanes, int top, int width, int height) const {
  std::vector<size_t> drawn{0};
  for (size_t lane = 1; !merged_ && lane < lanes.lanes().size(); ++lane)
    if (shown(lane)) drawn.push_back(lane);
  const size_t count = drawn.size();
  int columns = 1, rows = 1;
  gridFor(count, columns, rows);
  std::vector<Rect> views;
  for (size_t i = 0; i < count; ++i) {
    const int column = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
    // Edges at whole fractions of the area, so the views tile it without gaps.
    const int left = width * column / columns, right = width * (column + 1) / columns;
    const int upper = height * row / rows, lower = height * (row + 1) / rows;
    // One pixel of sky between views keeps them apart.
    const int gap = count > 1 ? 1 : 0;
    views.push_back({left, top + upper, std::max(1, right - left - gap), std::max(1, lower - upper - gap), drawn[i]});
  }
  return views;
}

void CompareViews::drawLabels(const CompareLanes& lanes, const std::vector<Rect>& views, HudText& text,
                              int windowWidth, int windowHeight) {
  const std::vector<CompareLanes::Lane>& all = lanes.lanes();
  while (labels_.size() < views.size()) {
    // Small and see-through: the label sits over the view's sky.
    labels_.push_back(std::make_unique<TextBlock>(LABEL_BOX_ALPHA));
    labels_.back()->useSmallFont(true);
  }
  for (size_t i = 0; i < views.size(); ++i) {
    std::vector<std::string> lines;
    // Merged: every shown engine's label in the one view, each headed by its colour.
    for (size_t lane = merged_ ? 0 : views[i].lane; lane < (merged_ ? all.size() : views[i].lane + 1); ++lane) {
      if (!shown(lane)) continue;
      std::vector<std::string> label = lanes.label(all[lane]);
      // Headed by the engine's colour (its outlines and its plot curve);
      // merged, ODE's bodies are the solid ones.
      if (merged_) {
        // One line an engine, its colour, name and headline (the version,
        // setting and notes are the views' labels'), so that the legend
        // stays low and short; without the aside, so a line fits a narrow view.
        const std::string colour = lane > 0 ? engineColour(all[lane].engine).name : "solid";
        const std::string headline = label.size() > 1 ? withoutAside(label[1]) : "";
        lines.push_back(colour + " " + all[lane].engine + (headline.empty() ? "" : ": " + headline));
        continue;
      }
      label.front() = std::string(engineColour(all[lane].engine).name) + ": " + label.front();
      lines.insert(lines.end(), label.begin(), label.end());
    }
    text.prepare(*labels_[i], lines, views[i].width - 2 * MARGIN);
    // A view a quarter of whose height the label would cover: the label
    // without its asides, at the bottom.
    const bool short_ = !merged_ && labels_[i]->height() * 4 > views[i].height;
    if (short_) {
      for (std::string& line : lines) line = withoutAside(line);
      text.prepare(*labels_[i], lines, views[i].width - 2 * MARGIN);
    }
    // Merged (and short), the legend sits at the view's bottom left, clear
    // of the scene's subject (test2's pivot is near the top); merged, a row
    // above the window's notice line.
    const int row = labels_[i]->height() / static_cast<int>(std::max<size_t>(1, lines.size()));
    const int above = merged_ ? 2 * row : 0;
    const int y = merged_ || short_
                      ? std::max(views[i].y + MARGIN, views[i].y + views[i].height - MARGIN - labels_[i]->height() - above)
                      : views[i].y + MARGIN;
    text.drawAt(*labels_[i], views[i].x + MARGIN, y, windowWidth, windowHeight);
  }
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

void CompareViews::drawOutlines(const CompareLanes& lanes, const glm::mat4& viewProjection) {
  outlines_.clear();
  const std::vector<CompareLanes::Lane>& all = lanes.lanes();
  for (size_t lane = 1; lane < all.size(); ++lane) {
    if (!all[lane].failure.empty() || !shown(lane)) continue;
    const Rgba color = colourOf(all[lane].engine, OUTLINE_ALPHA);
    const auto& ode = all.front().scene->run().objects();
    const auto& theirs = all[lane].scene->run().objects();
    for (size_t i = 0; i < theirs.size(); ++i) {
      const AbstractObject& object = *theirs[i];
      if (!object.visible || object.isFixed()) continue;
      const bool matched = i < ode.size() && ode[i]->shape() == object.shape();
      if (!matched || apart(ode[i]->getGeom(), object.getGeom())) outline(outlines_, object, color);
    }
  }
  drawLines(viewProjection);
}

void CompareViews::drawEdges(const AbstractWindow& scene, const std::string& engine, const glm::mat4& viewProjection) {
  outlines_.clear();
  const Rgba color = colourOf(engine, EDGE_ALPHA);
  for (const auto& object : scene.run().objects())
    if (object->visible && object->edged) outline(outlines_, *object, color);
  drawLines(viewProjection);
}

void CompareViews::drawLines(const glm::mat4& viewProjection) {
  if (outlines_.size() == 0) return;
  stream_.upload(outlines_);
  program_.use(viewProjection);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);  // over ODE's bodies: a body inside another shows
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  stream_.draw(GL_LINES, 0, outlines_.size());
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

std::vector<LivePlot::Curve> CompareViews::curves(const CompareLanes& lanes) const {
  std::vector<LivePlot::Curve> curves;
  const std::vector<CompareLanes::Lane>& all = lanes.lanes();
  for (size_t lane = 1; lane < all.size(); ++lane) {
    if (!shown(lane)) continue;
    const Rgba color = colourOf(all[lane].engine, 255);
    curves.push_back({&all[lane].scene->session().chart(), color});
  }
  return curves;
}

std::string CompareViews::legend(const CompareLanes& lanes) const {
  const std::vector<CompareLanes::Lane>& all = lanes.lanes();
  std::vector<std::string> engines;
  for (size_t lane = 0; lane < all.size(); ++lane)
    if (shown(lane)) engines.push_back(all[lane].engine);
  return colourLegend(engines);
}

std::string CompareViews::hudLine() const {
  return compareLayoutLine(merged_);
}

std::string CompareViews::helpLine() {
  return "M            compare: one view per engine / merged: ODE's bodies, and each other engine's outlined where "
         "it is 5 mm or 1 degree from ODE's";
}

}  // namespace odelab
