#include "Screenshot.h"

#include <GL/glew.h>

#include <stdexcept>
#include <cstring>
#include <vector>

#include "../SafeFile.h"
#include "RenderError.h"

// The one place stb_image_write's code is compiled. Static, so it cannot
// clash with the copy inside Debian's libstb should that be linked too.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace odelab {

namespace {
#ifdef __EMSCRIPTEN__
// WebGL2 reads the default framebuffer as RGBA only.
const int CHANNELS = 4;
const GLenum PIXEL_FORMAT = GL_RGBA;
#else
const int CHANNELS = 3;
const GLenum PIXEL_FORMAT = GL_RGB;
#endif
}  // namespace

void saveScreenshot(const std::string& path, int width, int height) {
  if (width <= 0 || height <= 0) throw RenderError("cannot save screenshot " + path + ": empty window");
  const std::size_t rowBytes = static_cast<std::size_t>(width) * CHANNELS;
  std::vector<unsigned char> pixels(rowBytes * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);  // rows of 3-byte pixels are not 4-aligned
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, PIXEL_FORMAT, GL_UNSIGNED_BYTE, pixels.data());

  // GL's first row is the bottom one; PNG's is the top.
  std::vector<unsigned char> flipped(pixels.size());
  for (int row = 0; row < height; ++row) {
    std::memcpy(&flipped[static_cast<std::size_t>(row) * rowBytes],
                &pixels[static_cast<std::size_t>(height - 1 - row) * rowBytes], rowBytes);
  }

  // stb tries five row filters per row and keeps the best; for rendered
  // frames (flat sky, shaded faces) plain rows compress as well or better and
  // take a fraction of the time, which --record pays every frame.
  stbi_write_force_png_filter = 0;
  // Encoded in memory, then written through writeFileAtomically: stb's own
  // file writer ignores write errors, so a full disk left a truncated PNG
  // and status 0; this way every write and the close are checked and the
  // file appears whole or not at all.
  int length = 0;
  unsigned char* png = stbi_write_png_to_mem(flipped.data(), static_cast<int>(rowBytes), width, height, CHANNELS, &length);
  if (!png) throw RenderError("cannot write screenshot " + path + ": PNG encoding failed");
  const std::string bytes(reinterpret_cast<const char*>(png), static_cast<std::size_t>(length));
  STBIW_FREE(png);
  try {
    writeFileAtomically(path, bytes);
  } catch (const std::runtime_error& error) {
    throw RenderError(std::string("screenshot: ") + error.what());
  }
}

}  // namespace odelab
