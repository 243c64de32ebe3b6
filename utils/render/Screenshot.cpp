#include "Screenshot.h"

#include <GL/glew.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

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

void saveScreenshot(const std::string& path, int width, int height) {
  if (width <= 0 || height <= 0) throw RenderError("cannot save screenshot " + path + ": empty window");
  const std::size_t rowBytes = static_cast<std::size_t>(width) * 3;
  std::vector<unsigned char> pixels(rowBytes * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);  // rows of 3-byte pixels are not 4-aligned
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());

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
  const std::string temporary = path + ".tmp";
  if (!stbi_write_png(temporary.c_str(), width, height, 3, flipped.data(), static_cast<int>(rowBytes))) {
    std::remove(temporary.c_str());
    throw RenderError("cannot write screenshot " + path);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw RenderError("cannot write screenshot " + path + ": " + reason);
  }
}

}  // namespace odelab
