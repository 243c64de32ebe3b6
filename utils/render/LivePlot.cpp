#include "LivePlot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

#include "EngineColours.h"

namespace odelab {

namespace {

const int MIN_BOX_WIDTH = 480;
const int MIN_BOX_HEIGHT = 220;
const int MARGIN = 10;   // from the window's edges
const int PADDING = 8;   // inside the box
// Room left of the plot for the value labels ("%.4g": at most 10
// characters such as -1.234e-05), in text lines: a character is narrower
// than half a line.
const int AXIS_LABEL_LINES = 5;
const Rgba BACKGROUND{12, 14, 18, 185};
const Rgba FRAME_COLOR{120, 130, 145, 255};
const Rgba ZERO_COLOR{80, 88, 100, 255};
const Rgba CHANGE_COLOR{255, 190, 70, 255};  // where a setting changed

// What the others' curves have drawn: their sample counts and last times summed.
double othersSignature(const std::vector<LivePlot::Curve>& others) {
  double sum = 0.0;
  for (const LivePlot::Curve& curve : others) {
    sum += static_cast<double>(curve.chart->samples().size());
    if (!curve.chart->samples().empty()) sum += curve.chart->samples().back().time;
  }
  return sum;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace

LivePlot::LivePlot(const std::string& shaderDir) : program_(shaderDir) {}

void LivePlot::rebuild(const StripChart& chart, const std::vector<Curve>& others, int viewportWidth,
                       int viewportHeight, int lineSkip) {
  const auto& samples = chart.samples();
  boxWidth_ = std::max(MIN_BOX_WIDTH, title_.width() + 2 * PADDING);
  boxHeight_ = std::max(MIN_BOX_HEIGHT, 11 * lineSkip);
  boxX_ = viewportWidth - boxWidth_ - MARGIN;
  boxY_ = viewportHeight - boxHeight_ - MARGIN;
  plotLeft_ = boxX_ + PADDING + AXIS_LABEL_LINES * lineSkip;
  plotRight_ = boxX_ + boxWidth_ - PADDING - 4;
  plotTop_ = boxY_ + PADDING + title_.height() + lineSkip / 2;
  plotBottom_ = boxY_ + boxHeight_ - PADDING - lineSkip - 4;

  // The value axis spans the finite samples, with a little room.
  double low = INFINITY, high = -INFINITY;
  for (const auto& s : samples)
    if (std::isfinite(s.value)) {
      low = std::min(low, s.value);
      high = std::max(high, s.value);
    }
  for (const Curve& curve : others)
    for (const auto& s : curve.chart->samples())
      if (std::isfinite(s.value)) {
        low = std::min(low, s.value);
        high = std::max(high, s.value);
      }
  if (!(low <= high)) low = high = 0.0;
  if (high - low < 1e-12 * std::max(1.0, std::fabs(high))) {
    const double pad = high != 0.0 ? std::fabs(high) * 0.1 : 1.0;
    low -= pad;
    high += pad;
  } else {
    // A little room, but an axis of values that never cross zero stays on its side.
    const double pad = 0.05 * (high - low);
    low = low >= 0.0 ? std::max(0.0, low - pad) : low - pad;
    high = high <= 0.0 ? std::min(0.0, high + pad) : high + pad;
  }
  minValue_ = low;
  maxValue_ = high;

  vertices_.clear();
  const float x0 = static_cast<float>(boxX_), y0 = static_cast<float>(boxY_);
  const float x1 = x0 + static_cast<float>(boxWidth_), y1 = y0 + static_cast<float>(boxHeight_);
  for (const glm::vec3& p : {glm::vec3(x0, y0, 0), glm::vec3(x1, y0, 0), glm::vec3(x1, y1, 0), glm::vec3(x0, y0, 0),
                             glm::vec3(x1, y1, 0), glm::vec3(x0, y1, 0)})
    vertices_.point(p, BACKGROUND);
  backgroundCount_ = vertices_.size();

  const float left = static_cast<float>(plotLeft_), right = static_cast<float>(plotRight_);
  const float top = static_cast<float>(plotTop_), bottom = static_cast<float>(plotBottom_);
  auto yOf = [&](double value) {
    return bottom - static_cast<float>((value - low) / (high - low)) * (bottom - top);
  };
  if (low < 0.0 && high > 0.0) vertices_.line({left, yOf(0.0), 0}, {right, yOf(0.0), 0}, ZERO_COLOR);
  vertices_.line({left, top, 0}, {right, top, 0}, FRAME_COLOR);
  vertices_.line({right, top, 0}, {right, bottom, 0}, FRAME_COLOR);
  vertices_.line({right, bottom, 0}, {left, bottom, 0}, FRAME_COLOR);
  vertices_.line({left, bottom, 0}, {left, top, 0}, FRAME_COLOR);

  if (samples.size() >= 2) {
    const double t0 = samples.front().time, t1 = samples.back().time;
    const double span = t1 > t0 ? t1 - t0 : 1.0;
    auto xOf = [&](double time) { return left + static_cast<float>((time - t0) / span) * (right - left); };
    // A setting changed (key or panel) at these times: a vertical mark.
    for (const double time : chart.changes())
      if (time >= t0 && time <= t1) vertices_.line({xOf(time), top, 0}, {xOf(time), bottom, 0}, CHANGE_COLOR);
    // The scene's own curve in ODE's colour, as a compare window's legend names it.
    const EngineColour& ode = engineColour("ode");
    addCurve(chart, {ode.r, ode.g, ode.b, 255}, t0, span);
    for (const Curve& curve : others) addCurve(*curve.chart, curve.color, t0, span);
  }
  lineCount_ = vertices_.size() - backgroundCount_;
  stream_.upload(vertices_);

  builtSamples_ = samples.size();
  builtChanges_ = chart.changes().size();
  builtFirst_ = samples.empty() ? 0.0 : samples.front().time;
  builtLast_ = samples.empty() ? 0.0 : samples.back().time;
  builtOthers_ = othersSignature(others);
  builtWidth_ = viewportWidth;
  builtHeight_ = viewportHeight;
  builtBoxWidth_ = title_.width();
}

// Segments between neighbouring finite samples within the time axis (t0 and
// its span, the leading chart's): a non-finite one leaves a gap.
void LivePlot::addCurve(const StripChart& chart, Rgba color, double t0, double span) {
  const float left = static_cast<float>(plotLeft_), right = static_cast<float>(plotRight_);
  const float top = static_cast<float>(plotTop_), bottom = static_cast<float>(plotBottom_);
  const double t1 = t0 + span;
  auto xOf = [&](double time) { return left + static_cast<float>((time - t0) / span) * (right - left); };
  auto yOf = [&](double value) {
    return bottom - static_cast<float>((value - minValue_) / (maxValue_ - minValue_)) * (bottom - top);
  };
  const auto& samples = chart.samples();
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const auto& a = samples[i - 1];
    const auto& b = samples[i];
    if (!std::isfinite(a.value) || !std::isfinite(b.value) || a.time < t0 || b.time > t1) continue;
    vertices_.line({xOf(a.time), yOf(a.value), 0}, {xOf(b.time), yOf(b.value), 0}, color);
  }
}

void LivePlot::draw(const StripChart& chart, HudText& text, int viewportWidth, int viewportHeight,
                    const std::vector<Curve>& others, const std::string& legend) {
  const auto& samples = chart.samples();
  std::string latest = "no samples yet";
  if (!samples.empty()) latest = "latest " + number(samples.back().value) + "  at t = " + number(samples.back().time) + " s";
  std::vector<std::string> title{chart.label.empty() ? std::string("live plot") : chart.label, latest};
  if (!legend.empty()) title.push_back(legend);
  text.prepare(title_, title);

  const bool changed = samples.size() != builtSamples_ || chart.changes().size() != builtChanges_ ||
                       (!samples.empty() && (samples.front().time != builtFirst_ || samples.back().time != builtLast_)) ||
                       othersSignature(others) != builtOthers_;
  if (changed || viewportWidth != builtWidth_ || viewportHeight != builtHeight_ || title_.width() != builtBoxWidth_)
    rebuild(chart, others, viewportWidth, viewportHeight, text.lineSkip());

  text.prepare(maxLabel_, {number(maxValue_)});
  text.prepare(minLabel_, {number(minValue_)});
  text.prepare(startLabel_, {samples.empty() ? std::string() : "t " + number(samples.front().time) + " s"});
  text.prepare(endLabel_, {samples.empty() ? std::string() : number(samples.back().time) + " s"});

  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  program_.use(glm::ortho(0.0f, static_cast<float>(viewportWidth), static_cast<float>(viewportHeight), 0.0f));
  glDisable(GL_MULTISAMPLE);  // as in DebugDraw: aliased lines are far cheaper in software
  stream_.draw(GL_TRIANGLES, 0, backgroundCount_);
  stream_.draw(GL_LINES, backgroundCount_, lineCount_);
  glEnable(GL_MULTISAMPLE);

  const int skip = text.lineSkip();
  text.drawAt(title_, boxX_ + PADDING, boxY_ + PADDING, viewportWidth, viewportHeight);
  text.drawAt(maxLabel_, plotLeft_ - 6 - maxLabel_.width(), plotTop_ - skip / 2, viewportWidth, viewportHeight);
  text.drawAt(minLabel_, plotLeft_ - 6 - minLabel_.width(), plotBottom_ - skip / 2, viewportWidth, viewportHeight);
  text.drawAt(startLabel_, plotLeft_, plotBottom_ + 3, viewportWidth, viewportHeight);
  text.drawAt(endLabel_, plotRight_ - endLabel_.width(), plotBottom_ + 3, viewportWidth, viewportHeight);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace odelab
