#include "render/surface_edges.h"

#include <algorithm>
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
  if (a.mesh != b.mesh || a.sphere != b.sphere || a.curve != b.curve || a.bsdf != b.bsdf) return true;
  if (glm::dot(a.ns, b.ns) < kCreaseCos) return true;
  return std::fabs(a.t - b.t) > kDepthJump * std::min(a.t, b.t);
}

std::vector<uint8_t> surfaceEdgePixels(const Accel& accel, const CameraModel& camera, int width, int height) {
  const long W = width, H = height;
  std::vector<uint8_t> edge(static_cast<size_t>(W) * static_cast<size_t>(H), 0);
  // Bands of rows, each traced with a one-row halo above and below: memory stays at a band's hits
  // (a whole image of Hits would be 0.8 GB at 4K) for 2/kBandRows more rays.
  constexpr long kBandRows = 32;
  const long bands = (H + kBandRows - 1) / kBandRows;
  parallelFor(static_cast<size_t>(bands), 1, [&](size_t b0, size_t b1) {
    std::vector<Ray> rays(static_cast<size_t>(W));
    std::vector<Hit> hits;
    for (size_t band = b0; band < b1; ++band) {
      const long y0 = static_cast<long>(band) * kBandRows, y1 = std::min(H, y0 + kBandRows);
      const long t0 = std::max(0L, y0 - 1), t1 = std::min(H, y1 + 1);  // traced rows, with the halo
      hits.assign(static_cast<size_t>((t1 - t0) * W), Hit{});
      for (long y = t0; y < t1; ++y) {
        for (long x = 0; x < W; ++x) rays[static_cast<size_t>(x)] = camera.generate(Vec2(x + 0.5f, y + 0.5f));
        accel.intersect(rays.data(), hits.data() + (y - t0) * W, static_cast<size_t>(W), true);
      }
      auto hitAt = [&](long x, long y) -> const Hit& { return hits[static_cast<size_t>((y - t0) * W + x)]; };
      for (long y = y0; y < y1; ++y)
        for (long x = 0; x < W; ++x) {
          const Hit& h = hitAt(x, y);
          bool differs = false;
          for (long ny = std::max(0L, y - 1); ny <= std::min(H - 1, y + 1) && !differs; ++ny)
            for (long nx = std::max(0L, x - 1); nx <= std::min(W - 1, x + 1) && !differs; ++nx)
              if (nx != x || ny != y) differs = surfacesDiffer(h, hitAt(nx, ny));
          edge[static_cast<size_t>(y * W + x)] = differs ? 1 : 0;
        }
    }
  });
  return edge;
}

}  // namespace rc
