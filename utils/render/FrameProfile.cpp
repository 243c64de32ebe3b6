#include "FrameProfile.h"

#include <algorithm>
#include <cstdio>

namespace odelab {

namespace {
const double AVERAGE_SECONDS = 1.0;
}

void FrameProfile::add(double collision, double stepping, double drawing, double swap, double frame) {
  collision_ += collision;
  stepping_ += stepping;
  drawing_ += drawing;
  swap_ += swap;
  frame_ += frame;
  ++frames_;
  if (frame_ < AVERAGE_SECONDS) return;
  const double perFrame = 1000.0 / static_cast<double>(frames_);
  char text[160];
  std::snprintf(text, sizeof text,
                "frame %.1f ms:   collision %.1f ms   step %.1f ms   drawing %.1f ms   swap %.1f ms   other %.1f ms",
                frame_ * perFrame, collision_ * perFrame, std::max(0.0, stepping_ - collision_) * perFrame,
                drawing_ * perFrame, swap_ * perFrame,
                std::max(0.0, frame_ - stepping_ - drawing_ - swap_) * perFrame);
  text_ = text;
  collision_ = stepping_ = drawing_ = swap_ = frame_ = 0;
  frames_ = 0;
}

}  // namespace odelab
