#pragma once

#include <string>

namespace odelab {

// Where a frame's time goes, averaged over about a second so that the
// figures can be read: collision (dSpaceCollide), the rest of stepping (the
// solver, the scene's own work), drawing the scene and its text, and the
// swap (where a software renderer finishes its work). Shown on the full HUD.
class FrameProfile {
 public:
  // One frame's parts, in seconds.
  void add(double collision, double stepping, double drawing, double swap, double frame);
  // "frame 41.2 ms: collision 1.2, step 3.4, drawing 20.1, swap 16.5 (ms a frame)";
  // empty until a second has been measured.
  const std::string& text() const { return text_; }

 private:
  double collision_ = 0, stepping_ = 0, drawing_ = 0, swap_ = 0, frame_ = 0;
  long long frames_ = 0;
  std::string text_;
};

}  // namespace odelab
