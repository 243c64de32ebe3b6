#pragma once

#include <string>
#include <vector>

namespace odelab {

// Result of looking for a resource: the first place that held it (empty when
// none did) and every place tried, in order, so an error can name them all.
struct ResourceLookup {
  std::string found;
  std::vector<std::string> tried;

  bool ok() const { return !found.empty(); }
  std::string triedList() const;  // "a, b, c"
};

// What a search may draw on. Kept as plain data so the order can be tested
// without touching the process environment or the file system layout.
struct ResourceSearch {
  std::string option;          // --shader-dir / --font; empty when not given
  std::string environment;     // ODELAB_SHADER_DIR / ODELAB_FONT; empty when unset
  std::string executableDir;   // directory of the running program
  std::string sourceDir;       // ODELAB_SOURCE_DIR, baked in at build time
};

// Where shaders are looked for, in order:
//   1. the --shader-dir option;  2. $ODELAB_SHADER_DIR;
//   3. <executable dir>/shaders;  4. <source tree>/shaders.
// An explicit choice (1 or 2) is the only place tried: a wrong path is an
// error to report, not something to paper over with a different copy.
std::vector<std::string> shaderDirCandidates(const ResourceSearch& search);

// Where the HUD font is looked for, in order:
//   1. the --font option;  2. $ODELAB_FONT;
//   3. <executable dir>/fonts/DejaVuSansMono.ttf;
//   4. <source tree>/fonts/DejaVuSansMono.ttf;
//   5. /usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf (fonts-dejavu-core).
// As for shaders, an explicit choice is the only place tried.
std::vector<std::string> fontCandidates(const ResourceSearch& search);

// A directory counts as the shader directory when it holds scene.vert.
bool isShaderDir(const std::string& path);
// A font candidate counts when it is a readable regular file.
bool isReadableFile(const std::string& path);

// The first candidate `accepts`, with every candidate tried up to it.
ResourceLookup findFirst(const std::vector<std::string>& candidates,
                         bool (*accepts)(const std::string& path));

// The searches with the real inputs: the option given, the environment,
// /proc/self/exe and the build-time source directory.
ResourceLookup findShaderDir(const std::string& option);
ResourceLookup findFont(const std::string& option);

// Directory of the running executable (from /proc/self/exe); empty if unknown.
std::string executableDirectory();

}  // namespace odelab
