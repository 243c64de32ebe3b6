#include "EnginePipe.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>
#include <thread>
#include <time.h>
#include <unistd.h>

#include "FormatValue.h"
#include "StopSignal.h"

extern char** environ;

namespace odelab::engines {

namespace {

// How long the destructor lets the child end by itself once its stdin is
// closed (Node ends at once) before it kills it.
constexpr auto GRACE = std::chrono::seconds(5);
// How often a wait for the child looks at the stop signal: the signal may
// have gone to another thread (a compare run's), so poll's EINTR is not
// enough.
constexpr int SLICE_MS = 100;

void closeFd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

// SIGPIPE blocked in this thread while it writes, and one that the write
// raised taken back before unblocking: the write fails with EPIPE instead
// of ending the program, and no other thread's signals change.
class SigpipeBlocked {
 public:
  SigpipeBlocked() {
    sigemptyset(&pipe_);
    sigaddset(&pipe_, SIGPIPE);
    sigset_t pending;
    sigpending(&pending);
    wasPending_ = sigismember(&pending, SIGPIPE) == 1;
    pthread_sigmask(SIG_BLOCK, &pipe_, &old_);
  }
  ~SigpipeBlocked() {
    if (!wasPending_) {
      const timespec zero{0, 0};
      while (sigtimedwait(&pipe_, nullptr, &zero) > 0) {
      }
    }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }

 private:
  sigset_t pipe_{}, old_{};
  bool wasPending_ = false;
};

}  // namespace

EnginePipe::EnginePipe(const std::vector<std::string>& argv) {
  int in[2], out[2];
  // O_CLOEXEC: the parent's ends never leak into this child or into another
  // engine's; posix_spawn's dup2 clears the flag on the child's 0 and 1.
  if (pipe2(in, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  if (pipe2(out, O_CLOEXEC) != 0) {
    ::close(in[0]);
    ::close(in[1]);
    throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  // The program ignores SIGPIPE and SIGXFSZ (StopSignal.h); the child gets
  // them at their defaults, as if started from a shell.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  sigaddset(&defaults, SIGXFSZ);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  const int error = posix_spawnp(&pid_, args[0], &actions, &attributes, args.data(), environ);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  ::close(in[0]);
  ::close(out[1]);
  toChild_ = in[1];
  fromChild_ = out[0];
  // Never blocked in write(2) by a child that stopped reading: writeLine
  // waits in poll, where the deadline and stop signals are seen.
  if (toChild_ >= 0) ::fcntl(toChild_, F_SETFL, ::fcntl(toChild_, F_GETFL) | O_NONBLOCK);
  if (error != 0) {
    closeFd(toChild_);
    closeFd(fromChild_);
    pid_ = -1;
    throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(error));
  }
}

EnginePipe::~EnginePipe() {
  finish();
  closeFd(fromChild_);
}

void EnginePipe::setDeadline(double seconds) {
  deadlineSeconds_ = seconds;
  deadline_ = std::chrono::steady_clock::now() +
              std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
}

void EnginePipe::kill(const std::string& why) {
  cutOff_ = why;
  closeFd(toChild_);
  closeFd(fromChild_);
  if (pid_ > 0 && !reaped_) {
    ::kill(pid_, SIGKILL);  // a stopped child (SIGSTOP) dies of it too
    reap(true);
  }
}

bool EnginePipe::waitReady(int fd, short events, const char* doing) {
  for (;;) {
    if (odelab::stopSignal() != 0) {
      kill(std::string(odelab::stopSignalName()) + " came while it was " + doing + "; it was ended (SIGKILL)");
      return false;
    }
    const auto left = deadline_ - std::chrono::steady_clock::now();
    if (left <= std::chrono::steady_clock::duration::zero()) {
      kill("no answer within " + formatValue(deadlineSeconds_) + " s, the deadline of that request, while it was " +
           doing + "; it was ended (SIGKILL)");
      return false;
    }
    const long long leftMs = std::chrono::duration_cast<std::chrono::milliseconds>(left).count() + 1;
    pollfd ready{fd, events, 0};
    const int n = ::poll(&ready, 1, static_cast<int>(std::min<long long>(leftMs, SLICE_MS)));
    if (n > 0) return true;  // readable, writable, or hung up: the read or write says which
    if (n < 0 && errno != EINTR) return true;  // let the read or write report it
  }
}

void EnginePipe::finish() {
  closeFd(toChild_);  // the server ends when its stdin does
  if (pid_ <= 0 || reaped_) return;
  const auto until = std::chrono::steady_clock::now() + GRACE;
  while (!reaped_ && std::chrono::steady_clock::now() < until) {
    reap(false);
    if (!reaped_) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (!reaped_) {
    ::kill(pid_, SIGKILL);
    reap(true);
  }
}

void EnginePipe::reap(bool wait) {
  if (reaped_ || pid_ <= 0) return;
  int status = 0;
  pid_t r;
  do {
    r = ::waitpid(pid_, &status, wait ? 0 : WNOHANG);
  } while (r < 0 && errno == EINTR);
  if (r == pid_ || r < 0) {
    reaped_ = true;
    status_ = r == pid_ ? status : 0;
  }
}

bool EnginePipe::writeLine(const std::string& line) {
  if (toChild_ < 0) return false;
  const std::string text = line + "\n";
  SigpipeBlocked blocked;
  size_t done = 0;
  while (done < text.size()) {
    // A child that stopped reading fills the pipe; the write waits no
    // longer than the request's deadline.
    if (!waitReady(toChild_, POLLOUT, "taking a message")) return false;
    const ssize_t n = ::write(toChild_, text.data() + done, text.size() - done);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) {
      closeFd(toChild_);
      return false;
    }
    done += static_cast<size_t>(n);
  }
  return true;
}

bool EnginePipe::readLine(std::string& line) {
  // Each byte is searched for the line's end once: a long line (a build's
  // reply holds every body's state) grows by chunks and only the new chunk is searched.
  size_t searched = 0;
  for (;;) {
    const size_t end = buffer_.find('\n', searched);
    searched = buffer_.size();
    if (end != std::string::npos) {
      line = buffer_.substr(0, end);
      buffer_.erase(0, end + 1);
      return true;
    }
    if (fromChild_ < 0) return false;
    if (!waitReady(fromChild_, POLLIN, "answering")) return false;
    char chunk[65536];
    const ssize_t n = ::read(fromChild_, chunk, sizeof chunk);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) {
      closeFd(fromChild_);
      return false;
    }
    buffer_.append(chunk, static_cast<size_t>(n));
  }
}

std::string EnginePipe::endedHow() {
  finish();
  if (!cutOff_.empty()) return cutOff_;
  if (WIFEXITED(status_)) return "exit status " + std::to_string(WEXITSTATUS(status_));
  if (WIFSIGNALED(status_)) return "killed by signal " + std::to_string(WTERMSIG(status_)) + " (" + strsignal(WTERMSIG(status_)) + ")";
  return "ended";
}

}  // namespace odelab::engines
