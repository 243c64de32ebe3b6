#include "SafeFile.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>

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

// The hidden name beside `path` that its temporary files start with: the
// replace stays within one file system, and mkstemp's suffix keeps two
// writers apart.
std::string temporaryStem(const std::string& path) { return folderOf(path) + "/." + nameOf(path) + "."; }

std::runtime_error failure(const std::string& path, const std::string& why) {
  return std::runtime_error("cannot write '" + path + "': " + why);
}

}  // namespace

std::string whyNotReplaceable(const std::string& path) {
  const platform::TargetFacts facts = platform::targetFacts(path, folderOf(path));
  // Absent (or its folder is: whyNotWritable says so) or a regular file.
  if (facts.kind != platform::FileKind::Absent && facts.kind != platform::FileKind::Regular)
    return platform::describe(facts.kind);
  // Written in place, the other names would change too; replaced, they
  // would keep the old contents while this one moves on.
  if (facts.links > 1) return "has more than one link (a hard link: another name shares its contents)";
  if (facts.anotherUsersInStickyFolder)
    return "is another user's file in a sticky folder, where only its owner may replace it";
  return {};
}

std::string whyNotWritable(const std::string& path) {
  const std::string folder = folderOf(path);
  const std::string resolved = platform::canonicalPath(folder);
  if (resolved.empty()) return "no such folder '" + folder + "'";
  if (platform::fileKind(resolved) != platform::FileKind::Folder) return "'" + folder + "' is not a folder";
  const std::string why = whyNotReplaceable(path);
  if (!why.empty()) return why;
  // The very name writeFileAtomically will use, made and removed: a name
  // too long for it, a folder that refuses new files, fail here, not after
  // the run.
  return platform::probeNewFile(temporaryStem(path));
}

std::string readBoundedFile(const std::string& path, std::size_t maxBytes, const std::string& what) {
  std::string bytes;
  const std::string why = platform::readRegularFile(path, maxBytes, bytes);
  if (!why.empty()) throw ReadRefused("cannot read " + what + " '" + path + "': " + why);
  return bytes;
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
  const std::string why = whyNotReplaceable(path);
  if (!why.empty()) throw failure(path, why + "; only a regular file is replaced");
  std::string temporary;
  try {
    temporary = platform::writeNewFile(temporaryStem(path), bytes);
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

bool sameFile(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  if (sameFilePath(a, b)) return true;
  std::error_code unknown;  // either absent: not one existing file
  return std::filesystem::equivalent(a, b, unknown) && !unknown;
}

std::FILE* openExclusiveOutput(const std::string& path) {
  using Refusal = platform::OutputFile::Refusal;
  const platform::OutputFile out = platform::openHeldOutput(path);
  switch (out.refusal) {
    case Refusal::None: return out.file;
    case Refusal::Link: throw failure(path, out.why + "; output files are never written through one");
    case Refusal::NotRegular: throw failure(path, out.why + "; output files are written only as regular files");
    case Refusal::Shared: throw failure(path, out.why + "; output files are written only to a file of their own");
    case Refusal::Held: throw failure(path, "another run is writing it now; give each run its own --out-dir");
    case Refusal::Failed: break;
  }
  throw failure(path, out.why);
}

}  // namespace odelab
