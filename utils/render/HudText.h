#pragma once

#include <GL/glew.h>
#include <SDL2/SDL_ttf.h>

#include <memory>
#include <string>
#include <vector>

#include "ShaderProgram.h"
#include "WindowLayout.h"

namespace odelab {

// One block of text lines rendered into a texture: the HUD, the help panel,
// a plot's labels. The texture is rebuilt only when the lines change, so a
// block whose text stays the same costs one quad per frame.
class TextBlock {
 public:
  // Alpha (0..255) of the dark backing box behind the text; 0: no box, no padding.
  explicit TextBlock(int boxAlpha = 170) : boxAlpha_(boxAlpha) {}
  ~TextBlock();
  TextBlock(const TextBlock&) = delete;
  TextBlock& operator=(const TextBlock&) = delete;

  // In HudText's smaller font (SMALL_PERCENT of the text height).
  void useSmallFont(bool small) { small_ = small; }
  // Size in pixels once prepared (HudText::prepare).
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  friend class HudText;
  int boxAlpha_;
  GLuint texture_ = 0;
  std::vector<std::string> lines_;
  int maxWidth_ = 0;
  int generation_ = -1;  // the HudText font size it was rendered with
  bool small_ = false;   // in HudText's smaller font
  bool renderedSmall_ = false;
  bool prepared_ = false;
  int width_ = 0, height_ = 0;
};

// Text over the scene with SDL2_ttf: the font, the quad shader, and the HUD
// block drawn in the window's top-left corner.
class HudText {
 public:
  // Opens the font and loads hud.* from shaderDir; throws RenderError.
  HudText(const std::string& fontPath, const std::string& shaderDir);
  ~HudText();
  HudText(const HudText&) = delete;
  HudText& operator=(const HudText&) = delete;

  // The HUD as a strip across the top of the view: `lines` broken between
  // items and laid out in as few columns (at most MAX_HUD_COLUMNS) as keep
  // it within `maxHeight` pixels. Returns the strip's height with its
  // margins (0 for no lines): the scene is drawn below it.
  // While the width, height limit, font, `small` and the first line (the
  // scene's title) stay the same, the layout is kept: each column starts at
  // the same line as before (lines added at the end join the last column)
  // and the strip never gets shorter, so a line that comes and goes (a
  // notice, a number that wraps) moves neither the view below nor the other
  // items.
  // `small`: in the smaller font (SMALL_PERCENT of the text height), for
  // the full HUD's many lines.
  // Lines marked in `oneRow` (notices, messages, figures that come and go)
  // are cut to one row each rather than broken over several.
  int layoutHud(const std::vector<std::string>& lines, int viewportWidth, int maxHeight, bool small = false,
                const std::vector<bool>& oneRow = {});
  // Draws the strip laid out last.
  void drawHud(int viewportWidth, int viewportHeight);
  static constexpr int SMALL_PERCENT = 80;

  // Text height in pixels: `pixels`, or when 0 one 45th of the window's
  // height within [12, 28] (16 at 720 rows). Re-renders blocks on a change.
  void setSizeFor(int pixels, int viewportHeight);

  // Renders `lines` into `block` unless it already shows them; then
  // block.width() / height() give its size for placing it. A line wider than
  // `maxWidth` pixels (0: no limit) wraps at spaces; a word wider still is
  // cut and ends in "...".
  void prepare(TextBlock& block, const std::vector<std::string>& lines, int maxWidth = 0);
  // For a monospaced font: the lines broken to fit and spread over as few
  // side-by-side columns (at most maxColumns) as keep them within
  // maxWidth x maxHeight pixels, joined into the lines of one block (for
  // prepare()). `fits` says whether they stay within maxHeight.
  std::vector<std::string> inColumns(const std::vector<std::string>& lines, int maxWidth, int maxHeight,
                                     int maxColumns, bool& fits);
  // Draws a prepared block with its top-left corner at pixel (x, y) from
  // the window's top-left corner. Leaves depth testing off and blending on.
  void drawAt(const TextBlock& block, int x, int y, int viewportWidth, int viewportHeight);

  int lineSkip() const { return TTF_FontLineSkip(font_.get()); }

 private:
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
  std::unique_ptr<TTF_Font, FontCloser> small_;
  ShaderProgram program_;
  GLint rectUniform_, viewportUniform_, textUniform_;
  GLuint emptyVertexArray_ = 0;  // core profile needs one bound even without attributes
  TextBlock hudColumns_[MAX_HUD_COLUMNS];
  int columnCount_ = 0, columnStep_ = 0;
  // The kept layout (layoutHud): what it was made for, where each column
  // starts, and the most rows the strip has had.
  // The first line (the title) stands for the scene: another scene on
  // screen (the launcher) gets a layout of its own.
  struct HudFit {
    int width = -1, maxHeight = -1, generation = -1;
    bool small = false;
    std::string title;
    bool operator==(const HudFit& o) const {
      return width == o.width && maxHeight == o.maxHeight && generation == o.generation && small == o.small &&
             title == o.title;
    }
  };
  HudFit hudFit_;
  std::vector<size_t> hudFirstLines_;
  size_t hudRows_ = 0;
  int pixels_ = 0;
  int generation_ = 0;
};

}  // namespace odelab
