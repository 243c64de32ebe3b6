#include "SafeFile.h"

#include <stdexcept>

#include "Platform.h"

namespace odelab {

namespace {

std::string folderOf(const std::string& path) {
  const auto slash = path.find_last_of(platform::FOLDER_SEPARATORS);
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string nameOf(const std::string& path) {
  const auto slash = path.find_last_of(platform::FOLDER_SEPARATORS);
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::runtime_error failure(const std::string& path, const std::string& why) {
  return std::runtime_error("cannot write '" + path + "': " + why);
}

}  // namespace

std::string whyNotReplaceable(const std::string& path) {
  const platform::FileKind kind = platform::fileKind(path);
  // Absent (or its folder is: checked elsewhere) or a regular file.
  if (kind == platform::FileKind::Absent || kind == platform::FileKind::Regular) return {};
  return platform::describe(kind);
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
  const std::string why = whyNotReplaceable(path);
  if (!why.empty()) throw failure(path, why + "; only a regular file is replaced");
  // A hidden name in the target folder: the replace stays within one file
  // system, and two writers never share a temporary file.
  std::string temporary;
  try {
    temporary = platform::writeNewFile(folderOf(path) + "/." + nameOf(path) + ".", bytes);
  } catch (const std::exception& error) {
    throw failure(path, error.what());
  }
  auto abandon = [&](const std::string& reason) {
    platform::removeFile(temporary);
    return failure(path, reason);
  };
  // Checked again just before the replace: what was planted meanwhile is
  // still not replaced (the replace itself never follows a link at `path`).
  const std::string whyNow = whyNotReplaceable(path);
  if (!whyNow.empty()) throw abandon(whyNow + "; only a regular file is replaced");
  const std::string replaced = platform::replaceFile(temporary, path);
  if (!replaced.empty()) throw abandon(replaced);
}

bool sameFilePath(const std::string& a, const std::string& b) {
  if (!platform::sameName(nameOf(a), nameOf(b))) return false;
  const std::string folderA = platform::canonicalPath(folderOf(a)), folderB = platform::canonicalPath(folderOf(b));
  return !folderA.empty() && platform::sameName(folderA, folderB);
}

std::FILE* openExclusiveOutput(const std::string& path) {
  using Refusal = platform::OutputFile::Refusal;
  const platform::OutputFile out = platform::openHeldOutput(path);
  switch (out.refusal) {
    case Refusal::None: return out.file;
    case Refusal::Link: throw failure(path, out.why + "; output files are never written through one");
    case Refusal::NotRegular: throw failure(path, out.why + "; output files are written only as regular files");
    case Refusal::Held: throw failure(path, "another run is writing it now; give each run its own --out-dir");
    case Refusal::Failed: break;
  }
  throw failure(path, out.why);
}

}  // namespace odelab
