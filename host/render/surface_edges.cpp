#include "render/surface_edges.h"

#include <cmath>

#include "core/parallel.h"

namespace rc {

namespace {
// A crease: shading normals more than ≈ 18° apart across one pixel. Curved surfaces turn by far
// less per pixel unless seen at a few pixels across, and then every pixel is worth a look.
constexpr float kCreaseCos = 0.95f;
// A depth jump: the distance changes by more than 10 % between neighbouring centres (an object
// in front of another of the same material; a plane at grazing incidence also qualifies, which
// only costs a few lookups).
constexpr float kDepthJump = 0.1f;
}  // namespace

bool surfacesDiffer(const Hit& a, const Hit& b) {
  if (a.valid() != b.valid()) return true;
  if (!a.valid()) return false;
  if (a.mesh != b.mesh || a.sphere != b.sphere || a.bsdf != b.bsdf) return true;
  if (glm::dot(a.ns, b.ns) < kCreaseCos) return true;
  return std::fabs(a.t - b.t) > kDepthJump * std::min(a.t, b.t);
}

std::vector<uint8_t> surfaceEdgePixels(const Accel& accel, const CameraModel& camera, int width, int height) {
  const size_t W = static_cast<size_t>(width), H = static_cast<size_t>(height);
  std::vector<Hit> hits(W * H);
  parallelFor(H, 4, [&](size_t y0, size_t y1) {
    std::vector<Ray> rays(W);
    for (size_t y = y0; y < y1; ++y) {
      for (size_t x = 0; x < W; ++x) rays[x] = camera.generate(Vec2(x + 0.5f, y + 0.5f));
      accel.intersect(rays.data(), hits.data() + y * W, W, true);
    }
  });
  std::vector<uint8_t> edge(W * H, 0);
  parallelFor(H, 16, [&](size_t y0, size_t y1) {
    for (size_t y = y0; y < y1; ++y)
      for (size_t x = 0; x < W; ++x) {
        const Hit& h = hits[y * W + x];
        bool differs = false;
        for (int dy = -1; dy <= 1 && !differs; ++dy)
          for (int dx = -1; dx <= 1 && !differs; ++dx) {
            const long nx = static_cast<long>(x) + dx, ny = static_cast<long>(y) + dy;
            if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= static_cast<long>(W) || ny >= static_cast<long>(H))
              continue;
            differs = surfacesDiffer(h, hits[static_cast<size_t>(ny) * W + static_cast<size_t>(nx)]);
          }
        edge[y * W + x] = differs ? 1 : 0;
      }
  });
  return edge;
}

}  // namespace rc
