#pragma once

#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace odelab {

// Writing files so that nothing is lost and nothing is replaced that should
// not be (doc/hardening.md, "What you can rely on").

// Writes `bytes` to a fresh, uniquely named temporary file in the folder of
// `path` (mkstemp: created, never opened through a planted link), checks
// every write and the close, then renames it over `path`. A `path` that
// exists and is not a regular file (a device, a FIFO, a symbolic link, a
// folder) is refused and left alone. Throws std::runtime_error naming
// `path`; the temporary file never outlives a failure.
void writeFileAtomically(const std::string& path, const std::string& bytes);

// "" when `path` may be replaced by writeFileAtomically or opened by
// openExclusiveOutput (absent, or a regular file with no other name that
// the system lets this user replace), else why not ("is a FIFO", "is a
// symbolic link", "has more than one link", ...).
std::string whyNotReplaceable(const std::string& path);

// The check before a run, one rule for every file a run writes (the metrics
// JSON, PNGs, the streamed outputs): "" when the write at the run's end
// will be allowed, else why not, so that a run that would fail late is
// refused before it starts. On top of whyNotReplaceable: the folder must
// exist ("no such folder"), and the hidden temporary file beside `path` is
// created for real, exclusively, and removed ("name is too long", "cannot
// create a file there: ..."). Nothing at `path` is changed. The cases every
// writer of the project meets: checks/file_rules.json.
std::string whyNotWritable(const std::string& path);

// The one reader of files a user names (recordings, scripts, shaders):
// reads `path` whole when it is a regular file of at most `maxBytes`;
// absent paths, folders, FIFOs (never opened, so nothing blocks), devices
// (/dev/zero is never read) and larger files are refused with a
// ReadRefused "cannot read <what> '<path>': <why>". Cases:
// checks/file_rules.json, "reader".
struct ReadRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};
std::string readBoundedFile(const std::string& path, std::size_t maxBytes, const std::string& what);

// True when the two paths name the same file once their folders are
// resolved (neither file has to exist; their folders do).
bool sameFilePath(const std::string& a, const std::string& b);
// True when `a` and `b` are one file: the same path (sameFilePath), or two
// names of one existing file (the same device and inode, through links:
// std::filesystem::equivalent). What a run reads is never what it writes.
bool sameFile(const std::string& a, const std::string& b);

// Opens `path` for a run's streamed output (Test2_output.txt and the like):
// never through a symbolic link, never a FIFO or device, never a file with
// another name (a hard link), and only while no
// other run holds it: an exclusive flock(2) taken before the file is
// truncated, held until the stream is closed, so a second run into the same
// --out-dir is refused instead of mixing its rows into the first run's file.
// Throws std::runtime_error naming `path`, with the reason.
std::FILE* openExclusiveOutput(const std::string& path);

}  // namespace odelab
