#include "SafeFile.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace odelab {

namespace {

std::string folderOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string nameOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string kindOf(mode_t mode) {
  if (S_ISLNK(mode)) return "is a symbolic link";
  if (S_ISDIR(mode)) return "is a folder";
  if (S_ISFIFO(mode)) return "is a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device";
  if (S_ISSOCK(mode)) return "is a socket";
  return "is not a regular file";
}

std::runtime_error failure(const std::string& path, const std::string& why) {
  return std::runtime_error("cannot write '" + path + "': " + why);
}

}  // namespace

std::string whyNotReplaceable(const std::string& path) {
  struct stat info {};
  if (lstat(path.c_str(), &info) != 0) return {};  // absent (or its folder is: checked elsewhere)
  return S_ISREG(info.st_mode) ? std::string() : kindOf(info.st_mode);
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
  const std::string why = whyNotReplaceable(path);
  if (!why.empty()) throw failure(path, why + "; only a regular file is replaced");
  // A hidden name in the target folder: the rename stays within one file
  // system, and two writers never share a temporary file.
  std::string pattern = folderOf(path) + "/." + nameOf(path) + ".XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = mkstemp(name.data());
  if (fd < 0) throw failure(path, std::string("cannot create a temporary file: ") + std::strerror(errno));
  const std::string temporary(name.data());
  auto abandon = [&](const std::string& reason) {
    unlink(temporary.c_str());
    return failure(path, reason);
  };
  // mkstemp makes the file 0600; give it the usual mode for new files.
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string reason = n < 0 ? std::strerror(errno) : "nothing written";
      close(fd);
      throw abandon(reason);
    }
    written += static_cast<size_t>(n);
  }
  if (close(fd) != 0) throw abandon(std::strerror(errno));
  // Checked again just before the rename: what was planted meanwhile is
  // still not replaced (rename itself never follows a link at `path`).
  const std::string whyNow = whyNotReplaceable(path);
  if (!whyNow.empty()) throw abandon(whyNow + "; only a regular file is replaced");
  if (std::rename(temporary.c_str(), path.c_str()) != 0) throw abandon(std::strerror(errno));
}

bool sameFilePath(const std::string& a, const std::string& b) {
  if (nameOf(a) != nameOf(b)) return false;
  char folderA[PATH_MAX], folderB[PATH_MAX];
  if (!realpath(folderOf(a).c_str(), folderA) || !realpath(folderOf(b).c_str(), folderB)) return false;
  return std::strcmp(folderA, folderB) == 0;
}

std::FILE* openExclusiveOutput(const std::string& path) {
  // O_NONBLOCK: opening a FIFO must not wait for a reader; O_NOFOLLOW: a
  // planted link fails instead of sending the rows to its target.
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0666);
  if (fd < 0) {
    if (errno == ELOOP) throw failure(path, "is a symbolic link; output files are never written through one");
    throw failure(path, std::strerror(errno));
  }
  struct stat info {};
  if (fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    close(fd);
    throw failure(path, kindOf(info.st_mode) + "; output files are written only as regular files");
  }
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    close(fd);
    if (error == EWOULDBLOCK)
      throw failure(path, "another run is writing it now; give each run its own --out-dir");
    throw failure(path, std::string("cannot lock it: ") + std::strerror(error));
  }
  // Truncated only once the lock is ours: a refused second run leaves the
  // first run's rows as they are.
  if (ftruncate(fd, 0) != 0 || fcntl(fd, F_SETFL, 0) != 0) {
    const int error = errno;
    close(fd);
    throw failure(path, std::strerror(error));
  }
  std::FILE* file = fdopen(fd, "w");
  if (!file) {
    close(fd);
    throw failure(path, std::strerror(errno));
  }
  return file;
}

}  // namespace odelab
