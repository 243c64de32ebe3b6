// The world reader's figures (doc/hardening.md, "Readers with a bound"):
//   world_read_tool ranges        the format's ranges as JSON (what doc/world.schema.json must state)
//   world_read_tool bench [N]     seconds and peak memory to read worlds of N/10 and N bodies (default 100000),
//                                 and to place an error's line in text nested MAX_JSON_DEPTH deep
// Figures printed, nothing asserted: the checks that bound these are in checks/readers.cmake.

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "FormatRanges.h"
#include "JsonLines.h"
#include "WorldJson.h"

namespace {

using odelab::world::WorldFileError;

// N boxes on a plane, one line each, as an exporter would write them.
std::string worldOf(int bodies) {
  std::string text = "{\"format\": \"odelab-world\", \"version\": 1, \"settings\": {\"step\": 0.001, \"gravity\": [0, -9.823, 0]},\n"
                     "\"bodies\": [\n";
  for (int i = 0; i < bodies; ++i)
    text += std::string(i ? ",\n" : "") + "{\"mass\": 1, \"inertia\": [0.1667, 0.1667, 0.1667, 0, 0, 0], \"position\": [" +
            std::to_string(i % 100) + ", " + std::to_string(1 + i / 10000) + ", " + std::to_string((i / 100) % 100) + "]}";
  text += "],\n\"geoms\": [{\"shape\": \"plane\", \"body\": -1, \"plane\": [0, 1, 0, 0]}";
  for (int i = 0; i < bodies; ++i) text += ",\n{\"shape\": \"box\", \"body\": " + std::to_string(i) + ", \"size\": [1, 1, 1]}";
  text += "],\n\"surfaces\": [{\"mu\": 0.5}]}\n";
  return text;
}

double peakMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux: KiB
}

double cpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// Wall and CPU seconds of f: on a shared machine the CPU time is the reader's own cost.
struct Took {
  double wall, cpu;
};
template <class F>
Took seconds(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  const double cpu = cpuSeconds();
  f();
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), cpuSeconds() - cpu};
}

void bench(int bodies) {
  for (int n : {bodies / 10, bodies}) {
    const std::string text = worldOf(n);
    std::size_t read = 0;
    const Took s = seconds([&] { read = odelab::world::worldFromJson(text).bodies.size(); });
    std::printf("read %zu bodies (%.1f MB): %.3f s CPU (%.3f s wall), peak memory %.0f MiB\n", read, text.size() / 1e6, s.cpu,
                s.wall, peakMiB());
    // The same world with its last body's mass wrong: the error's line is found by one more pass.
    std::string bad = text;
    bad.replace(bad.rfind("{\"mass\": 1,"), 11, "{\"mass\": -1,");
    std::string message;
    const Took e = seconds([&] {
      try {
        odelab::world::worldFromJson(bad);
      } catch (const WorldFileError& error) {
        message = error.what();
      }
    });
    std::printf("  refused for its last body's mass -1: %.3f s CPU (%.3f s wall): %s\n", e.cpu, e.wall, message.c_str());
  }
  // Nesting at the bound (accepted by the scan, then refused as not a world) and past it.
  for (int depth : {odelab::world::MAX_JSON_DEPTH, 100000}) {
    const std::string nested = std::string(depth, '[') + std::string(depth, ']');
    std::string message;
    const Took s = seconds([&] {
      try {
        odelab::world::worldFromJson(nested);
      } catch (const WorldFileError& error) {
        message = error.what();
      }
    });
    std::printf("%d nested arrays (%zu bytes): refused in %.4f s CPU, peak memory %.0f MiB: %s\n", depth, nested.size(), s.cpu,
                peakMiB(), message.c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::strcmp(argv[1], "ranges") == 0) {
    std::fputs(odelab::world::limits::rangesAsJson().c_str(), stdout);
    return 0;
  }
  if (argc >= 2 && std::strcmp(argv[1], "bench") == 0) {
    bench(argc >= 3 ? std::atoi(argv[2]) : 100000);
    return 0;
  }
  std::fprintf(stderr, "usage: world_read_tool ranges | bench [bodies]\n");
  return 2;
}
