#include "ResourcePaths.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>

// CMake defines the source tree's root so that programs run from the build
// directory find shaders without installing them.
#ifndef ODELAB_SOURCE_DIR
#define ODELAB_SOURCE_DIR ""
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

ResourceSearch realSearch(const std::string& option, const char* environmentName) {
  return {option, environmentValue(environmentName), executableDirectory(), ODELAB_SOURCE_DIR};
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
  if (!search.executableDir.empty()) candidates.push_back(join(search.executableDir, "shaders"));
  if (!search.sourceDir.empty()) candidates.push_back(join(search.sourceDir, "shaders"));
  return candidates;
}

std::vector<std::string> fontCandidates(const ResourceSearch& search) {
  const std::string chosen = explicitChoice(search);
  if (!chosen.empty()) return {chosen};
  std::vector<std::string> candidates;
  if (!search.executableDir.empty()) candidates.push_back(join(join(search.executableDir, "fonts"), FONT_NAME));
  if (!search.sourceDir.empty()) candidates.push_back(join(join(search.sourceDir, "fonts"), FONT_NAME));
  candidates.push_back(SYSTEM_FONT);
  return candidates;
}

bool isReadableFile(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return false;
  return std::ifstream(path).good();
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
  std::string buffer(4096, '\0');
  const ssize_t length = ::readlink("/proc/self/exe", buffer.data(), buffer.size());
  if (length <= 0 || static_cast<std::size_t>(length) >= buffer.size()) return "";
  buffer.resize(static_cast<std::size_t>(length));
  const std::size_t slash = buffer.rfind('/');
  if (slash == std::string::npos) return "";
  return slash == 0 ? "/" : buffer.substr(0, slash);
}

}  // namespace odelab
