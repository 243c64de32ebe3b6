#include "ResourcePaths.h"

#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "Platform.h"
#include "SafeFile.h"

// CMake defines the source tree's root so that programs run from the build
// directory find shaders without installing them, the build folder so that
// only those programs do, and the install's data folder as seen from its
// program folder (GNUInstallDirs: bin -> ../share/odelab).
#ifndef ODELAB_SOURCE_DIR
#define ODELAB_SOURCE_DIR ""
#endif
#ifndef ODELAB_BUILD_DIR
#define ODELAB_BUILD_DIR ""
#endif
#ifndef ODELAB_DATA_FROM_BINARY
#define ODELAB_DATA_FROM_BINARY "../share/odelab"
#endif

namespace odelab {

namespace {

const char* const FONT_NAME = "DejaVuSansMono.ttf";
const char* const SYSTEM_FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";

std::string environmentValue(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

std::string join(const std::string& directory, const std::string& name) {
  if (directory.empty() || directory.back() == '/') return directory + name;
  return directory + "/" + name;
}

// The explicit choices (option first, then environment) shadow everything
// else; returns the chosen one, or empty when the user chose nothing.
std::string explicitChoice(const ResourceSearch& search) {
  return search.option.empty() ? search.environment : search.option;
}

// The path with symbolic links resolved, as /proc/self/exe gives the
// program's; the path itself when it does not exist.
std::string resolved(const std::string& path) {
  if (path.empty()) return path;
  const std::string canonical = platform::canonicalPath(path);
  return canonical.empty() ? path : canonical;
}

ResourceSearch realSearch(const std::string& option, const char* environmentName) {
  const std::string executableDir = executableDirectory();
  return {option, environmentValue(environmentName), executableDir,
          installedDataDirectory(executableDir, ODELAB_DATA_FROM_BINARY),
          sourceTreeFor(executableDir, resolved(ODELAB_BUILD_DIR), ODELAB_SOURCE_DIR)};
}

}  // namespace

std::string ResourceLookup::triedList() const {
  std::string list;
  for (const std::string& path : tried) list += (list.empty() ? "" : ", ") + path;
  return list;
}

std::vector<std::string> shaderDirCandidates(const ResourceSearch& search) {
  const std::string chosen = explicitChoice(search);
  if (!chosen.empty()) return {chosen};
  std::vector<std::string> candidates;
  for (const std::string* folder : {&search.executableDir, &search.installedDataDir, &search.sourceDir})
    if (!folder->empty()) candidates.push_back(join(*folder, "shaders"));
  return candidates;
}

std::vector<std::string> fontCandidates(const ResourceSearch& search) {
  const std::string chosen = explicitChoice(search);
  if (!chosen.empty()) return {chosen};
  std::vector<std::string> candidates;
  for (const std::string* folder : {&search.executableDir, &search.installedDataDir, &search.sourceDir})
    if (!folder->empty()) candidates.push_back(join(join(*folder, "fonts"), FONT_NAME));
  candidates.push_back(SYSTEM_FONT);
  return candidates;
}

std::string installedDataDirectory(const std::string& executableDir, const std::string& dataFromBinary) {
  if (executableDir.empty() || dataFromBinary.empty()) return "";
  std::string folder = (std::filesystem::path(executableDir) / dataFromBinary).lexically_normal().string();
  if (folder.size() > 1 && folder.back() == '/') folder.pop_back();
  return folder;
}

std::string sourceTreeFor(const std::string& executableDir, const std::string& buildDir,
                          const std::string& sourceDir) {
  if (executableDir.empty() || buildDir.empty()) return sourceDir;
  const bool inside = executableDir == buildDir || executableDir.rfind(join(buildDir, ""), 0) == 0;
  return inside ? sourceDir : "";
}

bool isReadableFile(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return false;
  return std::ifstream(path).good();
}

std::string readSmallRegularFile(const std::string& path, std::size_t maxBytes) {
  return readBoundedFile(path, maxBytes, "the file");
}

bool isShaderDir(const std::string& path) { return isReadableFile(join(path, "scene.vert")); }

ResourceLookup findFirst(const std::vector<std::string>& candidates, bool (*accepts)(const std::string& path)) {
  ResourceLookup lookup;
  for (const std::string& candidate : candidates) {
    lookup.tried.push_back(candidate);
    if (accepts(candidate)) {
      lookup.found = candidate;
      break;
    }
  }
  return lookup;
}

ResourceLookup findShaderDir(const std::string& option) {
  return findFirst(shaderDirCandidates(realSearch(option, "ODELAB_SHADER_DIR")), isShaderDir);
}

ResourceLookup findFont(const std::string& option) {
  return findFirst(fontCandidates(realSearch(option, "ODELAB_FONT")), isReadableFile);
}

std::string executableDirectory() {
  const std::string program = platform::executablePath();
  const std::size_t slash = program.rfind('/');
  if (slash == std::string::npos) return "";
  return slash == 0 ? "/" : program.substr(0, slash);
}

}  // namespace odelab
