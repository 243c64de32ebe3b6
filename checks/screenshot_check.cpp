// screenshot_check: does a window screenshot show a lit scene with shadows?
//
//   screenshot_check FILE.png [--size WxH] [--region X0,Y0,X1,Y1]
//
// Exit 0 when every check passes, 1 when one fails, 2 on a usage error.
// Prints what it measured either way.
//
// The checks:
//  1. the image has the expected size (--size, default 1280x720);
//  2. it is not blank: the standard deviation of luminance over the whole
//     image is at least MIN_STDDEV (a cleared window, or one flat colour,
//     gives about 0);
//  3. one surface shows a shadow cast on its lit part. The renderer's
//     ambient light is white, so a shadow darkens a surface without changing
//     its chromaticity (r, g, b divided by r + g + b). Within the analysed
//     region (--region, fractions of the image; by default all but the top
//     quarter, where the HUD sits), pixels are grouped by chromaticity; for
//     each of the largest groups ("surfaces") the lit level is its 90th
//     percentile of luminance. A pixel of the surface is
//       lit       when its luminance is >= LIT_RATIO x the lit level,
//       shadowed  when it is < SHADOW_RATIO x the lit level (a shadowed
//                 upward face is about 0.35x in this renderer), and
//       cast      when it is shadowed and, along its row or its column, lit
//                 pixels of the same surface lie within ENCLOSURE_PIXELS on
//                 both sides.
//     The last condition tells a shadow cast onto a face (a dark patch inside
//     a lit area) from a face merely turned away from the light, such as the
//     platform's front edge under the lit top or a sphere's dark side, which
//     border the lit part on one side only. The surface passes with at least
//     MIN_LIT_FRACTION of its pixels lit and max(MIN_SHADOW_PIXELS,
//     MIN_SHADOW_FRACTION of its pixels) cast-shadow pixels.
//     Very dark and clipped pixels are skipped: their chromaticity is noise.
#include "check_cli.h"
#include "stb_image_once.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

const double MIN_STDDEV = 8.0;            // luminance, 0..255
const int MIN_CHROMA_SUM = 45;            // r + g + b below this: chromaticity unreliable
const int MAX_CHANNEL = 250;              // clipped highlights say nothing about the surface
const double CHROMA_TOLERANCE = 0.012;    // same surface when chromaticities are this close
const double MIN_SURFACE_FRACTION = 0.01; // of the region's pixels, for a group to be a surface
const int CANDIDATE_SURFACES = 8;
const double LIT_RATIO = 0.8;
const double SHADOW_RATIO = 0.5;
const double MIN_LIT_FRACTION = 0.2;
const double MIN_SHADOW_FRACTION = 0.001;
const int MIN_SHADOW_PIXELS = 80;
const int ENCLOSURE_PIXELS = 300;
const int CHROMA_BINS = 100;              // per axis, over [0, 1]

struct Options {
  std::string path;
  int width = 1280, height = 720;
  double region[4] = {0.0, 0.25, 1.0, 1.0};
};

struct Pixel {
  int x, y;  // in the region
  double luminance;
  double chromaR, chromaG;
};

enum Class : unsigned char { OTHER, LIT, SHADOWED };

// Counts SHADOWED cells with a LIT cell within `reach` on both sides along
// their row or their column of the width x height grid.
long countEnclosed(const std::vector<unsigned char>& grid, int width, int height, int reach) {
  // For one line of cells (start, stride, length): marks the enclosed ones.
  std::vector<unsigned char> enclosed(grid.size(), 0);
  auto scan = [&](std::size_t start, std::size_t stride, int length) {
    std::vector<int> lastLit(static_cast<std::size_t>(length)), nextLit(static_cast<std::size_t>(length));
    int last = -1000000;
    for (int i = 0; i < length; ++i) {
      if (grid[start + i * stride] == LIT) last = i;
      lastLit[static_cast<std::size_t>(i)] = last;
    }
    int next = 1000000;
    for (int i = length - 1; i >= 0; --i) {
      if (grid[start + i * stride] == LIT) next = i;
      nextLit[static_cast<std::size_t>(i)] = next;
    }
    for (int i = 0; i < length; ++i) {
      const std::size_t at = start + i * stride;
      if (grid[at] == SHADOWED && i - lastLit[static_cast<std::size_t>(i)] <= reach &&
          nextLit[static_cast<std::size_t>(i)] - i <= reach)
        enclosed[at] = 1;
    }
  };
  for (int y = 0; y < height; ++y) scan(static_cast<std::size_t>(y) * width, 1, width);
  for (int x = 0; x < width; ++x) scan(static_cast<std::size_t>(x), static_cast<std::size_t>(width), height);
  long count = 0;
  for (unsigned char e : enclosed) count += e;
  return count;
}

double luminanceOf(const unsigned char* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  const std::size_t index = static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(index), values.end());
  return values[index];
}

// Mean chromaticity of the most populated histogram bins, skipping bins whose
// mean lies within the tolerance of one already chosen (the same surface).
std::vector<std::pair<double, double>> candidateSurfaces(const std::vector<Pixel>& pixels) {
  struct Bin {
    long count = 0;
    double sumR = 0, sumG = 0;
  };
  std::vector<Bin> bins(CHROMA_BINS * CHROMA_BINS);
  for (const Pixel& p : pixels) {
    const int r = std::min(CHROMA_BINS - 1, static_cast<int>(p.chromaR * CHROMA_BINS));
    const int g = std::min(CHROMA_BINS - 1, static_cast<int>(p.chromaG * CHROMA_BINS));
    Bin& bin = bins[static_cast<std::size_t>(r * CHROMA_BINS + g)];
    ++bin.count;
    bin.sumR += p.chromaR;
    bin.sumG += p.chromaG;
  }
  std::sort(bins.begin(), bins.end(), [](const Bin& a, const Bin& b) { return a.count > b.count; });
  std::vector<std::pair<double, double>> centres;
  for (const Bin& bin : bins) {
    if (bin.count == 0 || static_cast<int>(centres.size()) == CANDIDATE_SURFACES) break;
    const double r = bin.sumR / bin.count, g = bin.sumG / bin.count;
    bool known = false;
    for (const auto& c : centres) known = known || std::hypot(c.first - r, c.second - g) < CHROMA_TOLERANCE;
    if (!known) centres.emplace_back(r, g);
  }
  return centres;
}

// Check 3 for one surface; prints its measurements.
bool surfaceShowsCastShadow(const std::vector<Pixel>& pixels, double chromaR, double chromaG, int regionWidth,
                            int regionHeight) {
  std::vector<const Pixel*> members;
  std::vector<double> luminances;
  for (const Pixel& p : pixels) {
    if (std::hypot(p.chromaR - chromaR, p.chromaG - chromaG) >= CHROMA_TOLERANCE) continue;
    members.push_back(&p);
    luminances.push_back(p.luminance);
  }
  const double count = static_cast<double>(members.size());
  const double regionPixels = static_cast<double>(regionWidth) * regionHeight;
  if (count < MIN_SURFACE_FRACTION * regionPixels) return false;
  const double lit = percentile(luminances, 0.9);
  std::vector<unsigned char> grid(static_cast<std::size_t>(regionWidth) * regionHeight, OTHER);
  long litCount = 0, shadowCount = 0;
  std::vector<double> shadowed;
  for (const Pixel* p : members) {
    unsigned char& cell = grid[static_cast<std::size_t>(p->y) * regionWidth + p->x];
    if (p->luminance >= LIT_RATIO * lit) {
      cell = LIT;
      ++litCount;
    } else if (p->luminance < SHADOW_RATIO * lit) {
      cell = SHADOWED;
      ++shadowCount;
      shadowed.push_back(p->luminance);
    }
  }
  const long castCount = countEnclosed(grid, regionWidth, regionHeight, ENCLOSURE_PIXELS);
  const double minShadow = std::max(static_cast<double>(MIN_SHADOW_PIXELS), MIN_SHADOW_FRACTION * count);
  const bool pass = litCount >= MIN_LIT_FRACTION * count && castCount >= minShadow;
  const double shadowMedian = percentile(shadowed, 0.5);
  std::printf("  surface chroma (%.3f, %.3f, %.3f): %ld px, lit level %.1f, lit %ld px (%.1f%%), "
              "shadowed %ld px (median %.2f x lit), cast %ld px (need %.0f) %s\n",
              chromaR, chromaG, 1.0 - chromaR - chromaG, static_cast<long>(count), lit, litCount,
              100.0 * litCount / count, shadowCount, lit > 0 ? shadowMedian / lit : 0.0, castCount, minShadow,
              pass ? "PASS" : "-");
  return pass;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"Checks a window screenshot: its size, not blank, and a shadow cast onto a lit surface. Exit 0 when "
               "every check passes, 1 when one fails.",
               "screenshot_check"};
  app.add_option("file", options.path, "the screenshot (PNG)")->required();
  app.add_option_function<std::string>(
         "--size",
         [&options](const std::string& text) {
           char tail = 0;
           if (std::sscanf(text.c_str(), "%dx%d%c", &options.width, &options.height, &tail) != 2 ||
               options.width < 1 || options.height < 1)
             throw CLI::ValidationError("--size", "'" + text + "' is not WxH");
         },
         "the image's expected size (default 1280x720)")
      ->type_name("WxH");
  checks::addRegion(app, options.region, "the region analysed, in fractions of the image (default 0,0.25,1,1)");
  if (auto status = checks::parse(app, argc, argv, [&options] {
        const double* r = options.region;
        if (!(0 <= r[0] && r[0] < r[2] && r[2] <= 1 && 0 <= r[1] && r[1] < r[3] && r[3] <= 1))
          throw CLI::ValidationError("--region", "needs 0 <= X0 < X1 <= 1 and 0 <= Y0 < Y1 <= 1");
      }))
    return *status;
  int width = 0, height = 0, channels = 0;
  unsigned char* data = stbi_load(options.path.c_str(), &width, &height, &channels, 3);
  if (!data) {
    std::printf("FAIL: cannot read %s: %s\n", options.path.c_str(), stbi_failure_reason());
    return 1;
  }
  std::vector<unsigned char> image(data, data + static_cast<std::size_t>(width) * height * 3);
  stbi_image_free(data);
  bool ok = true;

  // 1. size
  const bool sizeOk = width == options.width && height == options.height;
  std::printf("size: %dx%d (expected %dx%d) %s\n", width, height, options.width, options.height,
              sizeOk ? "ok" : "FAIL");
  ok = ok && sizeOk;

  // 2. not blank
  double sum = 0, sumSquares = 0;
  const std::size_t total = static_cast<std::size_t>(width) * height;
  for (std::size_t i = 0; i < total; ++i) {
    const double l = luminanceOf(&image[i * 3]);
    sum += l;
    sumSquares += l * l;
  }
  const double mean = total ? sum / total : 0.0;
  const double stddev = total ? std::sqrt(std::max(0.0, sumSquares / total - mean * mean)) : 0.0;
  const bool variedOk = stddev >= MIN_STDDEV;
  std::printf("luminance: mean %.1f, stddev %.1f (need >= %.1f) %s\n", mean, stddev, MIN_STDDEV,
              variedOk ? "ok" : "FAIL");
  ok = ok && variedOk;

  // 3. lit and shadowed parts of one surface
  const int x0 = static_cast<int>(options.region[0] * width), x1 = static_cast<int>(options.region[2] * width);
  const int y0 = static_cast<int>(options.region[1] * height), y1 = static_cast<int>(options.region[3] * height);
  std::vector<Pixel> pixels;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const unsigned char* p = &image[(static_cast<std::size_t>(y) * width + x) * 3];
      const int s = p[0] + p[1] + p[2];
      if (s < MIN_CHROMA_SUM || std::max({p[0], p[1], p[2]}) > MAX_CHANNEL) continue;
      pixels.push_back({x - x0, y - y0, luminanceOf(p), static_cast<double>(p[0]) / s, static_cast<double>(p[1]) / s});
    }
  }
  const std::size_t regionPixels = static_cast<std::size_t>(std::max(0, x1 - x0)) * std::max(0, y1 - y0);
  std::printf("region x %d..%d, y %d..%d: %zu px, %zu with usable colour\n", x0, x1, y0, y1, regionPixels,
              pixels.size());
  bool shadowOk = false;
  for (const auto& centre : candidateSurfaces(pixels))
    shadowOk = surfaceShowsCastShadow(pixels, centre.first, centre.second, x1 - x0, y1 - y0) || shadowOk;
  std::printf("shadow cast on a lit surface: %s\n", shadowOk ? "ok" : "FAIL (no surface shows one)");
  ok = ok && shadowOk;

  std::printf("%s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}
