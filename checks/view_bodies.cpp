// view_bodies: does every view of a compare window's screenshot show the
// bodies where the first view (ODE's) shows them?
//
//   view_bodies FILE.png --view X,Y,W,H --view X,Y,W,H ... [--skip-top F]
//
// Each --view is a view's rectangle in pixels from the top left, as the
// compare window prints them ("view bullet: x .. y .. width .. height .."),
// ODE's first. The scenes' bodies are drawn in saturated colours, and the
// sky, the checkered ground and the shadows are not: a pixel whose
// saturation, (max - min) / max of its channels, is at least MIN_SATURATION
// and whose brightest channel is at least MIN_VALUE is a body's. Below the
// top F of each view (its label; default 0.3), every view must have at
// least MIN_BODY_PIXELS body pixels, and their centroid, in fractions of the
// view's width and height, must lie within MAX_OFFSET of the first view's:
// the same bodies, seen by the same camera, in about the same place. Exit 0
// when every view does, 1 when one does not, 2 on a usage error. Prints
// what it measured either way.
#include "check_cli.h"
#include "stb_image_once.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

const double MIN_SATURATION = 0.5;  // the sky is about 0.28, the ground and shadows less
const int MIN_VALUE = 60;           // darker pixels' hue is noise
const long MIN_BODY_PIXELS = 40;
const double MAX_OFFSET = 0.05;

struct View {
  int x = 0, y = 0, width = 0, height = 0;
};

struct Seen {
  long pixels = 0;
  double x = 0.0, y = 0.0;  // the centroid, in fractions of the view
};

Seen bodiesIn(const unsigned char* image, int imageWidth, int imageHeight, const View& v, double skipTop) {
  Seen seen;
  double sumX = 0.0, sumY = 0.0;
  const int top = v.y + static_cast<int>(skipTop * v.height);
  for (int y = std::max(top, 0); y < std::min(v.y + v.height, imageHeight); ++y)
    for (int x = std::max(v.x, 0); x < std::min(v.x + v.width, imageWidth); ++x) {
      const unsigned char* p = image + 3 * (static_cast<long>(y) * imageWidth + x);
      const int high = std::max({p[0], p[1], p[2]}), low = std::min({p[0], p[1], p[2]});
      if (high < MIN_VALUE || high - low < MIN_SATURATION * high) continue;
      ++seen.pixels;
      sumX += x - v.x;
      sumY += y - v.y;
    }
  if (seen.pixels > 0) {
    seen.x = sumX / static_cast<double>(seen.pixels) / v.width;
    seen.y = sumY / static_cast<double>(seen.pixels) / v.height;
  }
  return seen;
}

}  // namespace

int main(int argc, char** argv) {
  std::string path;
  std::vector<std::string> given;
  double skipTop = 0.3;
  CLI::App app{"Checks that every view of a compare window's screenshot shows the bodies where the first view does; "
               "exit 0 when so, 1 when not.",
               "view_bodies"};
  app.add_option("image", path, "the screenshot (PNG)")->required();
  app.add_option("--view", given, "a view: X,Y,W,H in pixels from the top left (ODE's first)")->required();
  app.add_option("--skip-top", skipTop, "the top fraction of each view left out (its label)")->check(CLI::Range(0.0, 0.9));
  std::vector<View> views;
  if (auto status = checks::parse(app, argc, argv, [&] {
        for (const std::string& text : given) {
          View v;
          char end = 0;
          if (std::sscanf(text.c_str(), "%d,%d,%d,%d%c", &v.x, &v.y, &v.width, &v.height, &end) != 4 || v.width <= 0 ||
              v.height <= 0 || v.x < 0 || v.y < 0)
            throw CLI::ValidationError("--view", "'" + text + "' is not X,Y,W,H with W and H above 0");
          views.push_back(v);
        }
      }))
    return *status;
  int width = 0, height = 0, channels = 0;
  unsigned char* image = stbi_load(path.c_str(), &width, &height, &channels, 3);
  if (!image) {
    std::printf("FAIL: cannot read %s as an image: %s\n", path.c_str(), stbi_failure_reason());
    return 1;
  }
  bool ok = true;
  Seen first;
  for (size_t i = 0; i < views.size(); ++i) {
    const View& v = views[i];
    const Seen seen = bodiesIn(image, width, height, v, skipTop);
    if (i == 0) first = seen;
    const double offset = std::max(std::abs(seen.x - first.x), std::abs(seen.y - first.y));
    const bool fine = seen.pixels >= MIN_BODY_PIXELS && offset <= MAX_OFFSET;
    ok = ok && fine;
    std::printf("%s: view %zu (%d, %d, %dx%d): %ld body pixels (need %ld), centroid (%.3f, %.3f) of the view, "
                "%.3f from the first view's (at most %.2f)\n",
                fine ? "ok" : "FAIL", i + 1, v.x, v.y, v.width, v.height, seen.pixels, MIN_BODY_PIXELS, seen.x, seen.y,
                offset, MAX_OFFSET);
  }
  stbi_image_free(image);
  std::printf("%s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}
