#pragma once

#include <string>

namespace odelab {

// Reads the bound read buffer (the window's back buffer, before the swap) of
// width x height pixels and writes it to `path` as an RGB PNG. The file is
// written under a temporary name and renamed, so a reader never sees half a
// PNG. Throws RenderError naming the path when it cannot be written.
void saveScreenshot(const std::string& path, int width, int height);

}  // namespace odelab
