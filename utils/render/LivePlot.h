#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "../StripChart.h"
#include "HudText.h"
#include "Lines.h"

namespace odelab {

// The live plot (L): the scene's strip chart in the window's bottom-right
// corner: its label and latest value, the value axis's maximum and minimum,
// the time span, and the curve of value against simulated time. The curve's
// vertices are rebuilt only when samples arrived (or the window was
// resized); the text blocks only when their text changed.
class LivePlot {
 public:
  explicit LivePlot(const std::string& shaderDir);

  // A curve beside the chart's, on the same axes: a compare window's other engines.
  struct Curve {
    const StripChart* chart;
    Rgba color;
  };
  // `others` are drawn over the chart's curve, each in its colour, and
  // `legend` (one line, "" for none) is shown under the title.
  void draw(const StripChart& chart, HudText& text, int viewportWidth, int viewportHeight,
            const std::vector<Curve>& others = {}, const std::string& legend = "");

 private:
  void rebuild(const StripChart& chart, const std::vector<Curve>& others, int viewportWidth, int viewportHeight,
               int lineSkip);
  void addCurve(const StripChart& chart, Rgba color, double t0, double span);

  LineProgram program_;
  VertexStream stream_;
  VertexList vertices_;
  std::size_t backgroundCount_ = 0, lineCount_ = 0;
  // What the vertices were built from.
  std::size_t builtSamples_ = static_cast<std::size_t>(-1);
  std::size_t builtChanges_ = 0;
  double builtFirst_ = 0.0, builtLast_ = 0.0;
  double builtOthers_ = 0.0;  // the others' sample counts and last times, summed
  int builtWidth_ = 0, builtHeight_ = 0, builtBoxWidth_ = 0;
  // Layout of the last build, in window pixels.
  int boxX_ = 0, boxY_ = 0, boxWidth_ = 0, boxHeight_ = 0;
  int plotLeft_ = 0, plotTop_ = 0, plotRight_ = 0, plotBottom_ = 0;
  double minValue_ = 0.0, maxValue_ = 0.0;

  TextBlock title_{0}, maxLabel_{0}, minLabel_{0}, startLabel_{0}, endLabel_{0};
};

}  // namespace odelab
