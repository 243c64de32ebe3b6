#pragma once

#include <GL/glew.h>

namespace odelab {

// An offscreen colour and depth buffer at a fraction of the view's size,
// stretched onto the window with linear filtering: a software renderer
// shades a fraction of the pixels (the HUD and the panel, drawn after, stay
// sharp). Scale 1 draws straight into the window.
class ScaledTarget {
 public:
  ScaledTarget() = default;
  ~ScaledTarget();
  ScaledTarget(const ScaledTarget&) = delete;
  ScaledTarget& operator=(const ScaledTarget&) = delete;

  void setScale(float scale) { scale_ = scale; }
  float scale() const { return scale_; }
  // Binds where the scene of the window's width x height view at x, y
  // (pixels from the bottom left) is drawn and sets the viewport to it (the
  // window itself at scale 1).
  void begin(int x, int y, int width, int height);
  // Stretches what was drawn onto that view of the window and binds the
  // window again, its viewport the view's.
  void present();

 private:
  void resize(int width, int height);

  float scale_ = 1.0f;
  GLuint framebuffer_ = 0, colour_ = 0, depth_ = 0;
  int bufferWidth_ = 0, bufferHeight_ = 0;  // allocated size
  int viewX_ = 0, viewY_ = 0, viewWidth_ = 0, viewHeight_ = 0;  // the window rectangle it stands for
  bool active_ = false;
};

}  // namespace odelab
