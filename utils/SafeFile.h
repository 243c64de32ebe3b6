#pragma once

#include <cstdio>
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

// "" when `path` may be replaced by writeFileAtomically (absent, or a
// regular file), else why not ("is a FIFO", "is a symbolic link", ...).
std::string whyNotReplaceable(const std::string& path);

// True when the two paths name the same file once their folders are
// resolved (neither file has to exist; their folders do).
bool sameFilePath(const std::string& a, const std::string& b);

// Opens `path` for a run's streamed output (Test2_output.txt and the like):
// never through a symbolic link, never a FIFO or device, and only while no
// other run holds it: an exclusive flock(2) taken before the file is
// truncated, held until the stream is closed, so a second run into the same
// --out-dir is refused instead of mixing its rows into the first run's file.
// Throws std::runtime_error naming `path`, with the reason.
std::FILE* openExclusiveOutput(const std::string& path);

}  // namespace odelab
