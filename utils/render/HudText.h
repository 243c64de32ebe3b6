#pragma once

#include <GL/glew.h>
#include <SDL2/SDL_ttf.h>

#include <memory>
#include <string>
#include <vector>

#include "ShaderProgram.h"

namespace odelab {

// The HUD: the scene's text lines rendered with SDL2_ttf over a dark
// translucent box into one texture, drawn in the window's top-left corner.
// The texture is rebuilt only when the text changes.
class HudText {
 public:
  // Opens the font and loads hud.* from shaderDir; throws RenderError.
  HudText(const std::string& fontPath, const std::string& shaderDir);
  ~HudText();
  HudText(const HudText&) = delete;
  HudText& operator=(const HudText&) = delete;

  void draw(const std::vector<std::string>& lines, int viewportWidth, int viewportHeight);

 private:
  void upload(const std::vector<std::string>& lines);

  // TTF_Init / TTF_Quit, reference-counted by SDL_ttf; first member so it
  // outlives the font.
  struct TtfLibrary {
    TtfLibrary();
    ~TtfLibrary();
  };
  struct FontCloser {
    void operator()(TTF_Font* font) const { TTF_CloseFont(font); }
  };
  TtfLibrary library_;
  std::unique_ptr<TTF_Font, FontCloser> font_;
  ShaderProgram program_;
  GLint rectUniform_, viewportUniform_, textUniform_;
  GLuint texture_ = 0;
  GLuint emptyVertexArray_ = 0;  // core profile needs one bound even without attributes
  std::vector<std::string> shownLines_;
  int textureWidth_ = 0, textureHeight_ = 0;
};

}  // namespace odelab
