#include "app/diff_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/image_metrics.h"
#include "render/image_io.h"

namespace rc {

namespace {

// Maps log10 of the relative squared error onto a blue→green→yellow→red ramp over [1e-5, 1].
Color heatColor(float relErr) {
  if (!std::isfinite(relErr)) return Color(1, 0, 1);
  const float t = std::clamp((std::log10(std::max(relErr, 1e-5f)) + 5.0f) / 5.0f, 0.0f, 1.0f);
  const Color stops[4] = {Color(0, 0, 0.5f), Color(0, 0.8f, 0.2f), Color(1, 1, 0), Color(1, 0, 0)};
  const float x = t * 3.0f;
  const int i = std::min(2, static_cast<int>(x));
  const float f = x - i;
  const Color display = stops[i] * (1 - f) + stops[i + 1] * f;
  // The PNG writer sRGB-encodes linear values; undo that so the ramp shows as designed.
  return glm::pow(display, Color(2.2f));
}

}  // namespace

int runDiff(const DiffArgs& args, std::ostream& out) {
  const Image a = readImage(args.a);
  const Image b = readImage(args.b);
  if (a.width != b.width || a.height != b.height)
    throw Error("diff: " + args.a + " is " + std::to_string(a.width) + "x" + std::to_string(a.height) + " but " + args.b +
                " is " + std::to_string(b.width) + "x" + std::to_string(b.height));
  const ImageError e = compareImages(a.pixels, b.pixels);
  char line[256];
  if (args.json) {
    std::snprintf(line, sizeof line, "{\"rmse\": %.9g, \"relmse\": %.9g, \"max_abs\": %.9g, \"non_finite\": %zu}\n", e.rmse,
                  e.relmse, e.maxAbs, e.nonFinite);
  } else {
    std::snprintf(line, sizeof line, "RMSE    %.6g\nrelMSE  %.6g\nmax abs %.6g\n%s", e.rmse, e.relmse, e.maxAbs,
                  e.nonFinite ? ("non-finite pixels " + std::to_string(e.nonFinite) + "\n").c_str() : "");
  }
  out << line;
  if (!args.heatmap.empty()) {
    const std::vector<float> err = relativeErrorMap(a.pixels, b.pixels);
    Image heat;
    heat.width = a.width;
    heat.height = a.height;
    heat.pixels.resize(err.size());
    for (size_t i = 0; i < err.size(); ++i) heat.pixels[i] = heatColor(err[i]);
    writeImage(heat, args.heatmap);
  }
  // The metrics cover finite pixels only; an image of NaNs must not pass as identical.
  if (e.nonFinite > 0)
    throw Error("diff: " + std::to_string(e.nonFinite) + " pixel(s) are NaN or infinite in " + args.a + " or " + args.b +
                " (the metrics above cover the finite ones)");
  return 0;
}

}  // namespace rc
