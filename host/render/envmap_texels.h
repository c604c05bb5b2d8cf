#pragma once
// The envmap's per-direction arithmetic (render/envmap_light.h states the mapping and the density):
// direction → (u, v), the bilinear texel lookup and the density there. Inline and
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
  // width × height texels, row-major, top row first, 4 floats each: scaled radiance, then the
  // sampling weight luminance · sin(θ_row) (render/envmap_light.h), so one bilinear gives both.
  const float* rgbw;
  float pdfScale;     // solid-angle density = interpolated weight × pdfScale / sinθ
  int width, height;  // after padding: width ≥ 2, height ≥ 3
  Mat3 toLocal;

  Vec3 local(const Vec3& dirWorld) const { return glm::normalize(toLocal * dirWorld); }
  // Indexed in int (the image holds fewer than 2³¹/4 texels): a 32-bit index is what a gather takes.
  Vec4 texel(int x, int y) const {
    const int k = 4 * (y * width + x);
    return Vec4(rgbw[k], rgbw[k + 1], rgbw[k + 2], rgbw[k + 3]);
  }

  // Bilinear radiance (xyz) and sampling weight (w) at (u, v) from envUv or a sample:
  // u ∈ [0, 1), v ∈ [0, 1].
  Vec4 bilinear(const Vec2& uv) const {
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
    const Vec4 top = (1.0f - tx) * texel(x0, y0) + tx * texel(x1, y0);
    const Vec4 bottom = (1.0f - tx) * texel(x0, y0 + 1) + tx * texel(x1, y0 + 1);
    return (1.0f - ty) * top + ty * bottom;
  }

  // Solid-angle density from a bilinear result's weight at a direction with this sinθ: 0 at the
  // poles (no solid angle).
  float density(const Vec4& interpolated, float sinTheta) const {
    const float d = interpolated.w * pdfScale / sinTheta;
    return sinTheta > 0.0f ? d : 0.0f;
  }
  static float sinThetaOf(const Vec3& d) { return std::sqrt(std::max(0.0f, d.x * d.x + d.z * d.z)); }
};

}  // namespace rc
