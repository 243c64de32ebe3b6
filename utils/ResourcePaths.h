#pragma once

#include <cstddef>
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
  std::string option;            // --shader-dir / --font; empty when not given
  std::string environment;       // ODELAB_SHADER_DIR / ODELAB_FONT; empty when unset
  std::string executableDir;     // directory of the running program
  std::string installedDataDir;  // the install's data folder seen from the program (installedDataDirectory)
  std::string sourceDir;         // the source tree, for a program run inside its build folder (sourceTreeFor)
};

// Where shaders are looked for, in order:
//   1. the --shader-dir option;  2. $ODELAB_SHADER_DIR;
//   3. <executable dir>/shaders (the build folder's copy);
//   4. <installed data dir>/shaders (after `cmake --install`);
//   5. <source tree>/shaders.
// An explicit choice (1 or 2) is the only place tried: a wrong path is an
// error to report, not something to paper over with a different copy.
std::vector<std::string> shaderDirCandidates(const ResourceSearch& search);

// Where the HUD font is looked for, in order:
//   1. the --font option;  2. $ODELAB_FONT;
//   3. <executable dir>/fonts/DejaVuSansMono.ttf;
//   4. <installed data dir>/fonts/DejaVuSansMono.ttf;
//   5. <source tree>/fonts/DejaVuSansMono.ttf;
//   6. /usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf (fonts-dejavu-core).
// As for shaders, an explicit choice is the only place tried.
std::vector<std::string> fontCandidates(const ResourceSearch& search);

// The install's data folder for a program in `executableDir`: the two
// joined and "..", "." resolved ("/opt/odelab/bin" and "../share/odelab" give
// "/opt/odelab/share/odelab"). Empty when either is unknown.
std::string installedDataDirectory(const std::string& executableDir, const std::string& dataFromBinary);

// The source tree a program may fall back on: `sourceDir` when the program
// runs inside `buildDir` (the build that knows that tree), or when either
// folder is unknown (no /proc/self/exe, or a build that names none); empty
// for an installed copy, which must find its own data and not the tree it
// happened to be built from.
std::string sourceTreeFor(const std::string& executableDir, const std::string& buildDir,
                          const std::string& sourceDir);

// A directory counts as the shader directory when it holds scene.vert.
bool isShaderDir(const std::string& path);
// A font candidate counts when it is a readable regular file.
bool isReadableFile(const std::string& path);
// The whole of `path`, a regular file of at most `maxBytes`, through the
// one bounded reader (readBoundedFile, SafeFile.h): a FIFO, a device such as
// /dev/zero, or a larger file is refused without waiting or reading it.
// Throws ReadRefused (a std::runtime_error) naming the path and why.
std::string readSmallRegularFile(const std::string& path, std::size_t maxBytes);
constexpr std::size_t MAX_SHADER_BYTES = 1 << 20;

// The first candidate `accepts`, with every candidate tried up to it.
ResourceLookup findFirst(const std::vector<std::string>& candidates,
                         bool (*accepts)(const std::string& path));

// The searches with the real inputs: the option given, the environment,
// /proc/self/exe and the build-time folders (source, build, data seen from
// the program's install folder).
ResourceLookup findShaderDir(const std::string& option);
ResourceLookup findFont(const std::string& option);

// Directory of the running executable (platform::executablePath); empty if unknown.
std::string executableDirectory();

}  // namespace odelab
