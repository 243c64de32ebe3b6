#include "ScaledTarget.h"

#include <algorithm>
#include <cmath>

#include "RenderError.h"

namespace odelab {

ScaledTarget::~ScaledTarget() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (colour_) glDeleteRenderbuffers(1, &colour_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
}

void ScaledTarget::resize(int width, int height) {
  if (!framebuffer_) {
    glGenFramebuffers(1, &framebuffer_);
    glGenRenderbuffers(1, &colour_);
    glGenRenderbuffers(1, &depth_);
  }
  glBindRenderbuffer(GL_RENDERBUFFER, colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw RenderError("the scaled scene's framebuffer is incomplete");
  bufferWidth_ = width;
  bufferHeight_ = height;
}

void ScaledTarget::begin(int x, int y, int width, int height) {
  viewX_ = x;
  viewY_ = y;
  viewWidth_ = width;
  viewHeight_ = height;
  active_ = scale_ < 1.0f;
  if (!active_) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(x, y, width, height);
    return;
  }
  const int w = std::max(1, static_cast<int>(std::lround(width * scale_)));
  const int h = std::max(1, static_cast<int>(std::lround(height * scale_)));
  if (w != bufferWidth_ || h != bufferHeight_) resize(w, h);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, w, h);
}

void ScaledTarget::present() {
  if (!active_) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, bufferWidth_, bufferHeight_, viewX_, viewY_, viewX_ + viewWidth_, viewY_ + viewHeight_,
                    GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(viewX_, viewY_, viewWidth_, viewHeight_);
}

}  // namespace odelab
