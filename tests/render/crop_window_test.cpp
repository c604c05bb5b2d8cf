// Crop windows (hdrfilm crop_offset_x/y, crop_width/height): the image has the window's size and
// shows the same window of the sensor — for the path tracer bit for bit with a box filter (pixel
// sample streams are keyed by the sensor pixel), and with a Gaussian filter in the window's
// interior (a border of the filter radius sees samples from outside the window in a full render).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/parallel.h"
#include "render/camera.h"
#include "render/path_integrator.h"
#include "render_test_scenes.h"

namespace rc {
namespace {

Image renderWith(Scene s, int x, int y, int w, int h) {
  s.film.cropX = x;
  s.film.cropY = y;
  s.film.cropWidth = w;
  s.film.cropHeight = h;
  const test::World world(std::move(s));
  RenderOptions o;
  o.spp = 4;
  o.seed = 9;
  return world.renderPath(o);
}

TEST(CropWindow, CameraRayOfCropPixelIsTheSensorPixelsRay) {
  Scene s = test::cornellLike(40, 30);
  s.film.cropX = 11;
  s.film.cropY = 4;
  s.film.cropWidth = 7;
  s.film.cropHeight = 9;
  const CameraModel full(s.camera, 40, 30), crop(s.camera, s.film);
  const Ray a = full.generate(Vec2(11.25f + 3.0f, 4.5f + 2.0f)), b = crop.generate(Vec2(3.25f, 2.5f));
  EXPECT_EQ(0, std::memcmp(&a.d, &b.d, sizeof a.d));
  EXPECT_FLOAT_EQ(full.pixelFootprint(2.0f), crop.pixelFootprint(2.0f));  // sensor pixels, not crop pixels
}

TEST(CropWindow, BoxFilterTileEqualsWindowOfFullRenderBitForBit) {
  setThreadCount(2);
  const Scene s = test::cornellLike(32, 24);
  const Image full = renderWith(s, 0, 0, 0, 0);
  const int x0 = 5, y0 = 7, w = 13, h = 9;
  const Image tile = renderWith(s, x0, y0, w, h);
  setThreadCount(0);
  ASSERT_EQ(tile.width, w);
  ASSERT_EQ(tile.height, h);
  int differing = 0;
  double mean = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Color& a = tile.pixels[static_cast<size_t>(y) * w + x];
      const Color& b = full.pixels[static_cast<size_t>(y + y0) * full.width + x + x0];
      if (std::memcmp(&a, &b, sizeof a) != 0) ++differing;
      mean += luminance(a);
    }
  EXPECT_EQ(differing, 0);
  EXPECT_GT(mean / (w * h), 0.01);  // not a black window
}

TEST(CropWindow, GaussianTileInteriorEqualsFullRender) {
  setThreadCount(2);
  Scene s = test::cornellLike(32, 24);
  s.film.filter = "gaussian";
  s.film.gaussianStddev = 0.5f;  // radius 2 px
  const Image full = renderWith(s, 0, 0, 0, 0);
  const int x0 = 6, y0 = 5, w = 16, h = 14, border = 3;  // ≥ ceil(radius) + 1
  const Image tile = renderWith(s, x0, y0, w, h);
  setThreadCount(0);
  double maxRel = 0.0;
  for (int y = border; y < h - border; ++y)
    for (int x = border; x < w - border; ++x) {
      const Color& a = tile.pixels[static_cast<size_t>(y) * w + x];
      const Color& b = full.pixels[static_cast<size_t>(y + y0) * full.width + x + x0];
      for (int c = 0; c < 3; ++c) maxRel = std::max(maxRel, std::fabs(double(a[c]) - b[c]) / (1e-6 + std::fabs(b[c])));
    }
  // Same samples and weights; only the order of the double sums differs (tiles meet elsewhere).
  EXPECT_LT(maxRel, 1e-5);
}

}  // namespace
}  // namespace rc
