#pragma once
// Closed-form images for end-to-end render tests: a radiance function's average over every pixel of a
// scene's film, and its spread over the pixel (one sample's noise under a box filter); and the floor
// scene most of them look at.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/camera.h"
#include "scene/scene.h"

namespace rc::test {

// A 10×10 diffuse floor (reflectance ρ) at z = 0 seen from (0, 0, 5) straight down, box filter.
inline std::string floorScene(const std::string& lights, float rho = 0.5f) {
  return "<scene version=\"3.0.0\">\n"
         "<sensor type=\"perspective\"><float name=\"fov\" value=\"60\"/>"
         "<transform name=\"to_world\"><lookat origin=\"0, 0, 5\" target=\"0, 0, 0\" up=\"0, 1, 0\"/></transform>"
         "<film type=\"hdrfilm\"><integer name=\"width\" value=\"24\"/><integer name=\"height\" value=\"24\"/>"
         "<rfilter type=\"box\"/></film></sensor>\n"
         "<shape type=\"rectangle\"><transform name=\"to_world\"><scale value=\"5\"/></transform>"
         "<bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"" + std::to_string(rho) + "\"/></bsdf></shape>\n" +
         lights + "\n</scene>\n";
}

struct PixelExpectation {
  float mean = 0.0f;    // average of radiance(p) over the pixel
  float spread = 0.0f;  // its standard deviation over the pixel: one sample's noise under a box filter
};

// radiance(camera ray) per pixel (16×16 positions per pixel).
template <class Radiance>
std::vector<PixelExpectation> expectedImage(const Scene& s, Radiance radiance) {
  const CameraModel cam(s.camera, s.film);
  const int w = s.film.imageWidth(), h = s.film.imageHeight();
  std::vector<PixelExpectation> out(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double sum = 0.0, sum2 = 0.0;
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) {
          const double v = radiance(cam.generate(Vec2(x + (i + 0.5f) / 16.0f, y + (j + 0.5f) / 16.0f)));
          sum += v;
          sum2 += v * v;
        }
      const double mean = sum / 256.0;
      out[size_t(y) * w + x] = {float(mean), float(std::sqrt(std::max(0.0, sum2 / 256.0 - mean * mean)))};
    }
  return out;
}

// radiance(p) over the points p of the floor z = 0 the camera sees.
template <class Radiance>
std::vector<PixelExpectation> expectedFloorImage(const Scene& s, Radiance radiance) {
  return expectedImage(s, [&](const Ray& r) { return radiance(r.o + (-r.o.z / r.d.z) * r.d); });
}

}  // namespace rc::test
