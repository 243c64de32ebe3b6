#include "Platform.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace odelab::platform {

const char* const FOLDER_SEPARATORS = "/";

namespace {

FileKind kindOfMode(mode_t mode) {
  if (S_ISREG(mode)) return FileKind::Regular;
  if (S_ISLNK(mode)) return FileKind::Link;
  if (S_ISDIR(mode)) return FileKind::Folder;
  if (S_ISFIFO(mode)) return FileKind::Fifo;
  if (S_ISCHR(mode) || S_ISBLK(mode)) return FileKind::Device;
  if (S_ISSOCK(mode)) return FileKind::Socket;
  return FileKind::Other;
}

}  // namespace

FileKind fileKind(const std::string& path) {
  struct stat info {};
  if (lstat(path.c_str(), &info) != 0) return FileKind::Absent;
  return kindOfMode(info.st_mode);
}

bool sameName(const std::string& a, const std::string& b) { return a == b; }

std::string canonicalPath(const std::string& path) {
  char buffer[PATH_MAX];
  return realpath(path.c_str(), buffer) ? std::string(buffer) : std::string();
}

std::string executablePath() {
  std::string buffer(4096, '\0');
  const ssize_t length = readlink("/proc/self/exe", buffer.data(), buffer.size());
  if (length <= 0 || static_cast<std::size_t>(length) >= buffer.size()) return "";
  buffer.resize(static_cast<std::size_t>(length));
  return buffer;
}

std::string writeNewFile(const std::string& stem, const std::string& bytes) {
  std::string pattern = stem + "XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = mkstemp(name.data());
  if (fd < 0) throw std::runtime_error(std::string("cannot create a temporary file: ") + std::strerror(errno));
  const std::string path(name.data());
  auto fail = [&](const std::string& reason) {
    unlink(path.c_str());
    return std::runtime_error(reason);
  };
  // mkstemp makes the file 0600; give it the usual mode for new files.
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask);
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string reason = n < 0 ? std::strerror(errno) : "nothing written";
      close(fd);
      throw fail(reason);
    }
    written += static_cast<std::size_t>(n);
  }
  if (close(fd) != 0) throw fail(std::strerror(errno));
  return path;
}

std::string replaceFile(const std::string& source, const std::string& target) {
  return std::rename(source.c_str(), target.c_str()) == 0 ? std::string() : std::strerror(errno);
}

void removeFile(const std::string& path) { unlink(path.c_str()); }

OutputFile openHeldOutput(const std::string& path) {
  const auto refuse = OutputFile::refused;
  OutputFile out;
  // O_NONBLOCK: opening a FIFO must not wait for a reader; O_NOFOLLOW: a
  // planted link fails instead of sending the rows to its target.
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0666);
  if (fd < 0) {
    if (errno == ELOOP) return refuse(OutputFile::Refusal::Link, describe(FileKind::Link));
    return refuse(OutputFile::Refusal::Failed, std::strerror(errno));
  }
  struct stat info {};
  if (fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    close(fd);
    return refuse(OutputFile::Refusal::NotRegular, describe(kindOfMode(info.st_mode)));
  }
  if (info.st_nlink > 1) {
    close(fd);
    return refuse(OutputFile::Refusal::Shared, "has more than one link (a hard link: another name shares its contents)");
  }
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    close(fd);
    if (error == EWOULDBLOCK) return refuse(OutputFile::Refusal::Held, "held by another process");
    return refuse(OutputFile::Refusal::Failed, std::string("cannot lock it: ") + std::strerror(error));
  }
  // Truncated only once the lock is ours: a refused second run leaves the
  // first run's rows as they are.
  if (ftruncate(fd, 0) != 0 || fcntl(fd, F_SETFL, 0) != 0) {
    const int error = errno;
    close(fd);
    return refuse(OutputFile::Refusal::Failed, std::strerror(error));
  }
  out.file = fdopen(fd, "w");
  if (!out.file) {
    const int error = errno;
    close(fd);
    return refuse(OutputFile::Refusal::Failed, std::strerror(error));
  }
  return out;
}

TargetFacts targetFacts(const std::string& path, const std::string& folder) {
  TargetFacts facts;
  struct stat info {};
  if (lstat(path.c_str(), &info) != 0) return facts;
  facts.kind = kindOfMode(info.st_mode);
  facts.links = static_cast<unsigned long>(info.st_nlink);
  struct stat home {};
  const uid_t me = geteuid();
  // rename(2)'s rule for sticky folders; root (CAP_FOWNER) is exempt.
  facts.anotherUsersInStickyFolder = me != 0 && stat(folder.c_str(), &home) == 0 && (home.st_mode & S_ISVTX) &&
                                     info.st_uid != me && home.st_uid != me;
  return facts;
}

std::string probeNewFile(const std::string& stem) {
  std::string pattern = stem + "XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = mkstemp(name.data());
  if (fd < 0) {
    if (errno == ENAMETOOLONG) return "name is too long: the hidden temporary file beside it cannot be named";
    return std::string("cannot create a file there: ") + std::strerror(errno);
  }
  close(fd);
  unlink(name.data());
  return "";
}

std::string readRegularFile(const std::string& path, std::size_t maxBytes, std::string& bytes) {
  // Looked at before opening: a FIFO is never opened (an open for reading
  // would wait for a writer), a device never read.
  struct stat info {};
  if (stat(path.c_str(), &info) != 0) return errno == ENOENT ? "does not exist" : std::strerror(errno);
  if (!S_ISREG(info.st_mode)) return describe(kindOfMode(info.st_mode));
  // O_NONBLOCK: a FIFO swapped in meanwhile is not waited on either; the
  // open file is looked at again, so what is checked is what is read.
  const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return std::strerror(errno);
  std::string why;
  if (fstat(fd, &info) != 0)
    why = std::strerror(errno);
  else if (!S_ISREG(info.st_mode))
    why = describe(kindOfMode(info.st_mode));
  else if (static_cast<unsigned long long>(info.st_size) > maxBytes)
    why = "is larger than " + std::to_string(maxBytes) + " bytes";
  if (why.empty()) {
    bytes.resize(static_cast<std::size_t>(info.st_size));
    std::size_t got = 0;
    while (got < bytes.size()) {
      const ssize_t n = read(fd, &bytes[got], bytes.size() - got);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      got += static_cast<std::size_t>(n);
    }
    if (got != bytes.size()) why = "could not be read whole";
  }
  close(fd);
  return why;
}

void onStopRequest(void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  // The terminal or session went away: a stop like the others (129), not a
  // kill that leaves the output files unmarked. Ignored stays ignored (nohup).
  // SIGUSR1, SIGUSR2 and SIGALRM (a timer someone set) would kill the run
  // unmarked, its temporary files left behind: they stop it like SIGTERM
  // (128 + N). Ignored stays ignored, as for SIGHUP.
  for (const int signal : {SIGHUP, SIGUSR1, SIGUSR2, SIGALRM}) {
    struct sigaction before {};
    if (sigaction(signal, nullptr, &before) == 0 && before.sa_handler != SIG_IGN) sigaction(signal, &action, nullptr);
  }
  // A reader that went away (`test2 | true`) and a file size limit
  // (ulimit -f) are failed writes, not deaths: with the signals ignored the
  // write fails with EPIPE or EFBIG, the writer that made it says so and
  // removes its temporary file. A run whose only lost write was to standard
  // output after its end (| true) ends as it ran; the engines' children
  // get both back at their defaults (EnginePipe).
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  sigaction(SIGPIPE, &ignore, nullptr);
  sigaction(SIGXFSZ, &ignore, nullptr);
}

}  // namespace odelab::platform
