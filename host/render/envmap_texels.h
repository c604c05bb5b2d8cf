#pragma once
// The envmap's per-direction arithmetic (render/envmap_light.h states the mapping and the density):
// direction → (u, v), the bilinear texel lookup and the density of a direction's cell. Inline and
// free of branches that a select cannot replace, so that EnvmapLight's one-direction calls and its
// pass over a wave of directions (envmap_light_batch.cpp, compiled for AVX2/AVX-512 as well) run
// the very same operations and round the same way.
#include <algorithm>
#include <cstddef>

#include "core/fast_trig.h"
#include "core/math.h"

namespace rc {

// Mitsuba's lat-long mapping of a local unit direction: (u, v) ∈ [0, 1) × [0, 1]. Inline float
// atan2 and acos (core/fast_trig.h) instead of libm's calls, to within a few float ulps of them.
inline Vec2 envUv(const Vec3& d) {
  float u = atan2Fast(d.x, -d.z) * (0.5f * kInvPi);
  u = u < 0.0f ? u + 1.0f : u;
  u = u >= 1.0f ? 0.0f : u;
  const float v = acosFast(glm::clamp(d.y, -1.0f, 1.0f)) * kInvPi;
  return Vec2(u, v);
}

// A view of an EnvmapLight's tables (owned by it).
struct EnvmapTexels {
  const float* rgb;         // width × height texels, row-major, top row first, scaled radiance
  const double* cellPdfUv;  // the W × (H − 1) cells' densities in (u, v)
  int width, height;        // after padding: width ≥ 2, height ≥ 3
  Mat3 toLocal;

  Vec3 local(const Vec3& dirWorld) const { return glm::normalize(toLocal * dirWorld); }
  // Indexed in int (the image holds fewer than 2³¹/3 texels): a 32-bit index is what a gather takes.
  Color texel(int x, int y) const {
    const int k = 3 * (y * width + x);
    return Color(rgb[k], rgb[k + 1], rgb[k + 2]);
  }

  // Bilinear radiance at (u, v) from envUv or a sample: u ∈ [0, 1), v ∈ [0, 1].
  Color bilinear(const Vec2& uv) const {
    const float fx = uv.x * width - 0.5f;  // texel x's centre at u = (x + 0.5) / W
    const float fy = uv.y * (height - 1);  // texel y's centre at v = y / (H − 1)
    int x0 = floorToInt(fx);
    const float tx = fx - static_cast<float>(x0);
    // For u ∈ [0, 1), x0 ∈ [−1, W − 1]: one +W wraps it. The clamp only keeps a NaN direction's
    // index inside the image (it changes no in-range value, and a select vectorises where the
    // remainder of an integer division would not).
    x0 = x0 < 0 ? x0 + width : x0;
    x0 = std::min(width - 1, std::max(0, x0));
    const int x1 = x0 + 1 < width ? x0 + 1 : 0;
    const int y0 = std::min(height - 2, std::max(0, floorToInt(fy)));
    const float ty = glm::clamp(fy - static_cast<float>(y0), 0.0f, 1.0f);
    const Color top = (1.0f - tx) * texel(x0, y0) + tx * texel(x1, y0);
    const Color bottom = (1.0f - tx) * texel(x0, y0 + 1) + tx * texel(x1, y0 + 1);
    return (1.0f - ty) * top + ty * bottom;
  }

  // The cell whose constant density covers (u, v): cell i spans the texel centres i and i + 1.
  size_t cellOf(const Vec2& uv) const {
    float s = uv.x - 0.5f / width;  // u − 0.5/W ∈ [i/W, (i+1)/W), wrapped
    s = s < 0.0f ? s + 1.0f : s;
    // The lower clamps keep a NaN's index inside the table (pdf() answers 0 for it anyway).
    const int i = std::max(0, std::min(width - 1, static_cast<int>(s * width)));
    const int j = std::max(0, std::min(height - 2, static_cast<int>(uv.y * (height - 1))));
    return static_cast<size_t>(j) * width + i;
  }

  // Solid-angle density of local direction d at its (u, v): 0 at the poles (no solid angle).
  float pdf(const Vec3& d, const Vec2& uv) const {
    const float sinTheta = std::sqrt(std::max(0.0f, d.x * d.x + d.z * d.z));
    const double density = cellPdfUv[cellOf(uv)] / (2.0 * kPiD * kPiD * sinTheta);
    return sinTheta > 0.0f ? static_cast<float>(density) : 0.0f;
  }
};

}  // namespace rc
