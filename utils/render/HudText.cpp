#include "HudText.h"

#include <algorithm>

#include "RenderError.h"
#include "TextColumns.h"
#include "WindowLayout.h"

namespace odelab {

namespace {

const int FONT_POINTS = 15;
const int PADDING = HUD_PADDING;
const int MARGIN = HUD_MARGIN;
const SDL_Color TEXT_COLOR{235, 238, 242, 255};

TTF_Font* openFont(const std::string& path) {
  TTF_Font* font = TTF_OpenFont(path.c_str(), FONT_POINTS);
  if (!font) throw ResourceError("cannot open font " + path + ": " + TTF_GetError());
  return font;
}

int textWidth(TTF_Font* font, const std::string& text) {
  int w = 0, h = 0;
  return TTF_SizeUTF8(font, text.c_str(), &w, &h) == 0 ? w : 0;
}

// Cuts `word` so that it and "..." fit in `maxWidth` (whole UTF-8 characters).
std::string elide(TTF_Font* font, std::string word, int maxWidth) {
  while (!word.empty() && textWidth(font, word + "...") > maxWidth) {
    do word.pop_back();
    while (!word.empty() && (static_cast<unsigned char>(word.back()) & 0xC0) == 0x80);
    if (!word.empty() && (static_cast<unsigned char>(word.back()) & 0xC0) == 0xC0) word.pop_back();
  }
  return word + "...";
}

// Every line broken between items to `maxWidth` pixels (TextColumns); a
// word wider than that still is cut and ends in "...".
std::vector<std::string> wrapLines(TTF_Font* font, const std::vector<std::string>& lines, int maxWidth) {
  if (maxWidth <= 0) return lines;
  std::vector<std::string> out = wrapItems(lines, maxWidth, [font](const std::string& text) { return textWidth(font, text); });
  for (std::string& line : out)
    if (textWidth(font, line) > maxWidth) line = elide(font, line, maxWidth);
  return out;
}

struct SurfaceFreer {
  void operator()(SDL_Surface* surface) const { SDL_FreeSurface(surface); }
};
using SurfacePtr = std::unique_ptr<SDL_Surface, SurfaceFreer>;

}  // namespace

TextBlock::~TextBlock() {
  if (texture_) glDeleteTextures(1, &texture_);
}

HudText::TtfLibrary::TtfLibrary() {
  if (TTF_Init() != 0) throw RenderError(std::string("cannot initialise SDL_ttf: ") + TTF_GetError());
}

HudText::TtfLibrary::~TtfLibrary() { TTF_Quit(); }

HudText::HudText(const std::string& fontPath, const std::string& shaderDir)
    : font_(openFont(fontPath)), small_(openFont(fontPath)), program_(shaderDir + "/hud.vert", shaderDir + "/hud.frag") {
  rectUniform_ = program_.uniform("uRect");
  viewportUniform_ = program_.uniform("uViewport");
  textUniform_ = program_.uniform("uText");
  glGenVertexArrays(1, &emptyVertexArray_);
}

HudText::~HudText() { glDeleteVertexArrays(1, &emptyVertexArray_); }

void HudText::setSizeFor(int pixels, int viewportHeight) {
  const int wanted = textPixelsFor(pixels, viewportHeight);
  if (wanted == pixels_) return;
  if (TTF_SetFontSize(font_.get(), wanted) != 0) return;  // keeps the size it had
  TTF_SetFontSize(small_.get(), std::max(11, wanted * SMALL_PERCENT / 100));
  pixels_ = wanted;
  ++generation_;
}

void HudText::prepare(TextBlock& block, const std::vector<std::string>& unwrapped, int maxWidth) {
  if (block.prepared_ && unwrapped == block.lines_ && maxWidth == block.maxWidth_ &&
      block.generation_ == generation_ && block.renderedSmall_ == block.small_)
    return;
  TTF_Font* font = block.small_ ? small_.get() : font_.get();
  const std::vector<std::string> lines = wrapLines(font, unwrapped, maxWidth - 2 * PADDING);
  // Render each line, then compose them onto one RGBA image whose bytes are
  // in R, G, B, A order whatever the machine's endianness (SDL_PIXELFORMAT_RGBA32).
  const int padding = block.boxAlpha_ > 0 ? PADDING : 0;
  std::vector<SurfacePtr> rendered;
  int width = 0;
  const int skip = TTF_FontLineSkip(font);
  for (const std::string& line : lines) {
    // TTF refuses empty strings; a blank line still takes its height.
    SurfacePtr surface(line.empty() ? nullptr : TTF_RenderUTF8_Blended(font, line.c_str(), TEXT_COLOR));
    if (surface) width = std::max(width, surface->w);
    rendered.push_back(std::move(surface));
  }
  width = std::max(width, 1) + 2 * padding;
  const int height = std::max(skip * static_cast<int>(lines.size()), 1) + 2 * padding;

  SurfacePtr image(SDL_CreateRGBSurfaceWithFormat(0, width, height, 32, SDL_PIXELFORMAT_RGBA32));
  if (!image) throw RenderError(std::string("cannot create text image: ") + SDL_GetError());
  SDL_FillRect(image.get(), nullptr, SDL_MapRGBA(image->format, 12, 14, 18, static_cast<Uint8>(block.boxAlpha_)));
  for (std::size_t i = 0; i < rendered.size(); ++i) {
    if (!rendered[i]) continue;
    SDL_Rect at{padding, padding + static_cast<int>(i) * skip, rendered[i]->w, rendered[i]->h};
    // Over a box, blend; with no box, copy the glyphs' own alpha.
    SDL_SetSurfaceBlendMode(rendered[i].get(), block.boxAlpha_ > 0 ? SDL_BLENDMODE_BLEND : SDL_BLENDMODE_NONE);
    SDL_BlitSurface(rendered[i].get(), nullptr, image.get(), &at);
  }

  if (!block.texture_) {
    glGenTextures(1, &block.texture_);
    glBindTexture(GL_TEXTURE_2D, block.texture_);
    // Drawn at exactly one texel per pixel: no filtering wanted.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glBindTexture(GL_TEXTURE_2D, block.texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, image->pitch / 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image->pixels);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  block.width_ = width;
  block.height_ = height;
  block.lines_ = unwrapped;
  block.maxWidth_ = maxWidth;
  block.generation_ = generation_;
  block.renderedSmall_ = block.small_;
  block.prepared_ = true;
}

void HudText::drawAt(const TextBlock& block, int x, int y, int viewportWidth, int viewportHeight) {
  if (!block.prepared_) return;
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  program_.use();
  glUniform4f(rectUniform_, static_cast<float>(x), static_cast<float>(y), static_cast<float>(block.width_),
              static_cast<float>(block.height_));
  glUniform2f(viewportUniform_, static_cast<float>(viewportWidth), static_cast<float>(viewportHeight));
  glUniform1i(textUniform_, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, block.texture_);
  glBindVertexArray(emptyVertexArray_);
  // A pixel-aligned quad has no edges to smooth; a software renderer would
  // still store every sample.
  glDisable(GL_MULTISAMPLE);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glEnable(GL_MULTISAMPLE);
  glBindVertexArray(0);
}

std::vector<std::string> HudText::inColumns(const std::vector<std::string>& lines, int maxWidth, int maxHeight,
                                            int maxColumns, bool& fits) {
  const int gapCharacters = 4;
  const TextWidth width = [this](const std::string& text) { return textWidth(font_.get(), text); };
  const int maxRows = std::max(1, (maxHeight - 2 * PADDING) / std::max(1, lineSkip()));
  const auto columns = spreadOverColumns(lines, maxWidth - 2 * PADDING, gapCharacters * width(" "), maxRows,
                                         maxColumns, width, Wrap::Hanging);
  std::vector<std::string> joined = joinColumns(columns, gapCharacters);
  fits = static_cast<int>(joined.size()) <= maxRows;
  return joined;
}

int HudText::layoutHud(const std::vector<std::string>& lines, int viewportWidth, int maxHeight, bool small,
                       const std::vector<bool>& oneRow) {
  if (lines.empty()) {
    columnCount_ = 0;
    return 0;
  }
  TTF_Font* font = small ? small_.get() : font_.get();
  const int totalWidth = std::max(80, viewportWidth - 2 * MARGIN);
  const TextWidth width = [font](const std::string& text) { return textWidth(font, text); };
  const auto tallest = [](const std::vector<std::vector<std::string>>& columns) {
    size_t rows = 0;
    for (const auto& column : columns) rows = std::max(rows, column.size());
    return rows;
  };
  const HudFit fit{viewportWidth, maxHeight, generation_, small, lines.front()};
  std::vector<std::vector<std::string>> columns;
  if (fit == hudFit_ && !hudFirstLines_.empty())
    columns = columnsFrom(lines, hudFirstLines_, hudTotalTextWidth(viewportWidth), hudColumnGap(), width, Wrap::Items,
                          oneRow);
  if (columns.empty()) {
    columns = hudColumns(lines, viewportWidth, maxHeight, TTF_FontLineSkip(font), width, oneRow, &hudFirstLines_).columns;
    if (!(fit == hudFit_)) hudRows_ = 0;
    hudFit_ = fit;
  }
  hudRows_ = std::max(hudRows_, tallest(columns));
  const int count = static_cast<int>(columns.size());
  const int columnWidth = (totalWidth - (count - 1) * MARGIN) / count;
  for (int i = 0; i < count; ++i) {
    // Equal heights, so the columns read as one strip.
    columns[i].resize(hudRows_);
    hudColumns_[i].small_ = small;
    prepare(hudColumns_[i], columns[i], count > 1 ? columnWidth : totalWidth);
  }
  columnCount_ = count;
  columnStep_ = count > 1 ? columnWidth + MARGIN : 0;
  return hudColumns_[0].height() + 2 * MARGIN;
}

void HudText::drawHud(int viewportWidth, int viewportHeight) {
  for (int i = 0; i < columnCount_; ++i)
    drawAt(hudColumns_[i], MARGIN + i * columnStep_, MARGIN, viewportWidth, viewportHeight);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace odelab
