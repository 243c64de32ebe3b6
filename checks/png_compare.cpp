// png_compare: how much of a region differs between two PNGs of one size?
//
//   png_compare A.png B.png [--region X0,Y0,X1,Y1] [--threshold T]
//               [--min-changed F] [--max-changed F]
//
// A pixel has changed when one of its channels differs by more than T
// (default 24, of 255). The region is given in fractions of the image
// (default: all of it). With --min-changed the changed fraction of the
// region must be at least F; with --max-changed at most F. Exit 0 when the
// images load, match in size and meet the bounds; 1 when they do not; 2 on a
// usage error. Prints what it measured either way. The windowed checks use
// it to see an overlay appear (the help panel: a large part of the middle
// changes) where nothing else moves (the scene is paused).
#include "check_cli.h"
#include "stb_image_once.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

struct Image {
  int width = 0, height = 0;
  unsigned char* pixels = nullptr;  // RGB
  ~Image() { stbi_image_free(pixels); }
};

bool load(const std::string& path, Image& image) {
  int channels = 0;
  image.pixels = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
  if (!image.pixels) std::printf("FAIL: cannot read %s as an image: %s\n", path.c_str(), stbi_failure_reason());
  return image.pixels != nullptr;
}

}  // namespace

int main(int argc, char** argv) {
  std::string pathA, pathB;
  double region[4] = {0, 0, 1, 1};
  int threshold = 24;
  double minChanged = -1.0, maxChanged = 2.0;
  CLI::App app{"Measures how much of a region differs between two PNGs of one size; exit 0 when the changed "
               "fraction is within the bounds, 1 when not.",
               "png_compare"};
  app.add_option("image_a", pathA, "the first PNG")->required();
  app.add_option("image_b", pathB, "the second PNG")->required();
  checks::addRegion(app, region, "the region compared, in fractions of the image (default: all of it)");
  app.add_option("--threshold", threshold, "a pixel has changed when a channel differs by more than T (of 255)")
      ->transform(checks::decimal())
      ->check(CLI::Range(0, 255));
  app.add_option("--min-changed", minChanged, "the changed fraction of the region must be at least F")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--max-changed", maxChanged, "the changed fraction of the region must be at most F")
      ->check(CLI::Range(0.0, 1.0));
  if (auto status = checks::parse(app, argc, argv)) return *status;
  Image a, b;
  if (!load(pathA, a) || !load(pathB, b)) return 1;
  if (a.width != b.width || a.height != b.height) {
    std::printf("FAIL: sizes differ: %dx%d and %dx%d\n", a.width, a.height, b.width, b.height);
    return 1;
  }
  const int x0 = std::clamp(static_cast<int>(region[0] * a.width), 0, a.width);
  const int x1 = std::clamp(static_cast<int>(region[2] * a.width), x0, a.width);
  const int y0 = std::clamp(static_cast<int>(region[1] * a.height), 0, a.height);
  const int y1 = std::clamp(static_cast<int>(region[3] * a.height), y0, a.height);
  long changed = 0, total = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const unsigned char* p = a.pixels + 3 * (static_cast<long>(y) * a.width + x);
      const unsigned char* q = b.pixels + 3 * (static_cast<long>(y) * b.width + x);
      int difference = 0;
      for (int c = 0; c < 3; ++c) difference = std::max(difference, std::abs(p[c] - q[c]));
      changed += difference > threshold ? 1 : 0;
      ++total;
    }
  const double fraction = total > 0 ? static_cast<double>(changed) / static_cast<double>(total) : 0.0;
  const bool ok = total > 0 && fraction >= minChanged && fraction <= maxChanged;
  std::printf("%s: %dx%d, region [%d, %d) x [%d, %d): %ld of %ld pixels changed (%.4f", ok ? "ok" : "FAIL", a.width,
              a.height, x0, x1, y0, y1, changed, total, fraction);
  if (minChanged >= 0) std::printf("; at least %.4f wanted", minChanged);
  if (maxChanged <= 1) std::printf("; at most %.4f wanted", maxChanged);
  std::printf(")\n");
  return ok ? 0 : 1;
}
