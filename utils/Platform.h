#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>

// What the operating system does differently, behind one set of calls:
// PlatformPosix.cpp (Linux and the like) and PlatformWindows.cpp (Windows,
// built with MinGW-w64); the build compiles one of them. Paths are the C
// library's narrow strings: on Windows in the ANSI code page, as main's
// arguments come, converted for the wide-character API; paths handed back
// have '/' between folders.
namespace odelab::platform {

// The folder separators a path may use: "/" on POSIX, "/\\" on Windows.
extern const char* const FOLDER_SEPARATORS;

// What a path names, without following a final symbolic link (on Windows,
// a reparse point: a symbolic link or a junction).
enum class FileKind { Absent, Regular, Folder, Link, Fifo, Device, Socket, Other };
FileKind fileKind(const std::string& path);
// "is a symbolic link", "is a FIFO", ...: why a kind other than Regular or
// Absent is not written to.
inline std::string describe(FileKind kind) {
  switch (kind) {
    case FileKind::Link: return "is a symbolic link";
    case FileKind::Folder: return "is a folder";
    case FileKind::Fifo: return "is a FIFO";
    case FileKind::Device: return "is a device";
    case FileKind::Socket: return "is a socket";
    default: return "is not a regular file";
  }
}

// True for two spellings of one file name: byte for byte on POSIX, ignoring
// case on Windows, whose file systems do.
bool sameName(const std::string& a, const std::string& b);
// The absolute path with "." and ".." and links resolved, or "" when the
// path does not exist.
std::string canonicalPath(const std::string& path);
// The running program's full path, or "" when it cannot be found.
std::string executablePath();

// Creates a new file whose name starts with `stem` and ends in a unique
// suffix (never opening an existing name, so never through a planted link),
// writes `bytes` to it and closes it, checking every write and the close.
// Returns its path; throws std::runtime_error with the reason, leaving no
// file behind.
std::string writeNewFile(const std::string& stem, const std::string& bytes);
// Puts `source` in the place of `target` in one step, so a reader sees the
// old file or the new one, never a mix: rename(2) on POSIX, MoveFileEx
// with MOVEFILE_REPLACE_EXISTING on Windows (whose rename fails when the
// target exists). A link at `target` is replaced, not followed. Returns ""
// or the reason it failed.
std::string replaceFile(const std::string& source, const std::string& target);
void removeFile(const std::string& path);

// Opens a run's streamed output file for writing, held by this process
// alone: on POSIX an exclusive flock(2), on Windows a handle that shares
// reading only, so a second writer's open fails. Refuses a symbolic link and
// anything not a regular file without writing to it, and truncates only once
// the file is held; a file with another name (a hard link) is refused too,
// before it is truncated. The stream is binary: rows end in "\n" on every
// system.
struct OutputFile {
  enum class Refusal { None, Link, NotRegular, Shared, Held, Failed };
  std::FILE* file = nullptr;  // set when refusal is None
  Refusal refusal = Refusal::None;
  std::string why;            // the reason, when refused
  static OutputFile refused(Refusal refusal, std::string why) { return {nullptr, refusal, std::move(why)}; }
};
OutputFile openHeldOutput(const std::string& path);

// What the check before a run learns of a write's target `path` in
// `folder` (not following a final link): its kind, how many names its
// contents have (more than one: a hard link, whose other names a write in
// place or a rename would change or cut off), and whether the system would
// refuse to replace it for its owner: in a sticky folder (/tmp) only the
// file's owner, the folder's owner or root may rename over a file.
struct TargetFacts {
  FileKind kind = FileKind::Absent;
  unsigned long links = 0;
  bool anotherUsersInStickyFolder = false;
};
TargetFacts targetFacts(const std::string& path, const std::string& folder);
// Creates a new file named `stem` plus a unique suffix, as writeNewFile
// does, and removes it at once: proof that a later write's temporary file
// can exist. "" or why not: "name is too long" past the file system's limit
// on a name, else "cannot create a file there: <the system's reason>".
std::string probeNewFile(const std::string& stem);

// Reads a whole regular file of at most `maxBytes` into `bytes`. Following
// links, what the path names is looked at before it is opened, so a FIFO is
// refused without waiting on it and a device (/dev/zero) without reading
// it; the open file is looked at again, so what is checked is what is read.
// Returns "" or why it was not read: "does not exist", "is a folder", "is a
// FIFO", "is a device", "is larger than N bytes", or the system's reason.
std::string readRegularFile(const std::string& path, std::size_t maxBytes, std::string& bytes);

// Calls `handler` with the signal's number when the user asks the program to
// stop: SIGINT and SIGTERM on POSIX; on Windows Ctrl+C and Ctrl+Break in the
// console (both given as SIGINT), the only stop requests a console program
// can catch there. Windows resets the handler before calling it, so there
// a second Ctrl+C ends the process whatever the handler does.
void onStopRequest(void (*handler)(int));

}  // namespace odelab::platform
