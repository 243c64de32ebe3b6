#pragma once

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "../CompareLanes.h"
#include "HudText.h"
#include "Lines.h"
#include "LivePlot.h"

namespace odelab {

// Where a compare window draws: one view per engine shown in a grid (two
// side by side, then two by two, then three columns), ODE's top left; or,
// merged (M), ODE's view alone with every other shown engine's bodies
// outlined over it where they are apart from ODE's, so a drift shows at
// once. Each view carries its label (CompareLanes::label). An engine the
// panel hides still steps with the others; only its view is left out.
class CompareViews {
 public:
  // A view in window pixels from the top left, and the lane it shows
  // (merged: ODE's, 0).
  struct Rect {
    int x, y, width, height;
    size_t lane = 0;
  };

  explicit CompareViews(const std::string& shaderDir);

  // The views of a scene area width x height (below the HUD's strip, which
  // is `top` pixels high): one per lane, or one when merged.
  std::vector<Rect> layout(const CompareLanes& lanes, int top, int width, int height) const;
  bool merged() const { return merged_; }
  void toggleMerged() { merged_ = !merged_; }
  // Whether lane `lane`'s engine is drawn (ODE's always is).
  bool shown(size_t lane) const { return lane == 0 || lane >= hidden_.size() || !hidden_[lane]; }
  void setShown(size_t lane, bool shown);

  // Each lane's label at the top left of its view (merged: every label in
  // one column, each in its engine's colour as a heading). `windowWidth` x
  // `windowHeight` is the whole window, the viewport when this is called.
  // A view too short for its whole label (seven engines in a grid) gets it
  // without the closing aside every engine shares, at its bottom left, clear
  // of the scene's subject as the merged legend is.
  void drawLabels(const CompareLanes& lanes, const std::vector<Rect>& views, HudText& text, int windowWidth,
                  int windowHeight);
  // Merged: every other lane's moving bodies that are apart from ODE's body
  // of the same index, outlined in its colour over ODE's view with
  // `viewProjection`; the viewport is that view's.
  void drawOutlines(const CompareLanes& lanes, const glm::mat4& viewProjection);
  // The edges of `scene`'s bodies that ask for them (AbstractObject::edged:
  // a world file's), in `engine`'s colour, with the same outline the merged
  // view draws; the viewport is that view's.
  void drawEdges(const AbstractWindow& scene, const std::string& engine, const glm::mat4& viewProjection);

  // The live plot (L): every other engine's curve in its colour, and the
  // legend naming each engine's colour (ODE's is the plot's own).
  std::vector<LivePlot::Curve> curves(const CompareLanes& lanes) const;
  std::string legend(const CompareLanes& lanes) const;

  // A line for the HUD: the layout and its key.
  std::string hudLine() const;
  // The key's line for the help.
  static std::string helpLine();

 private:
  void drawLines(const glm::mat4& viewProjection);  // outlines_, over what is drawn

  LineProgram program_;
  VertexStream stream_;
  VertexList outlines_;
  std::vector<std::unique_ptr<TextBlock>> labels_;
  bool merged_ = false;
  std::vector<bool> hidden_;  // per lane
};

}  // namespace odelab
