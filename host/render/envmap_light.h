#pragma once
// The lat-long environment emitter (`envmap`) with the semantics of Mitsuba 3's
// src/emitters/envmap.cpp, which defines the format:
//   direction d (emitter-local, +y up) ↔ (u, v) = (atan2(d.x, −d.z) / 2π, acos(d.y) / π);
//   radiance = scale × bilinear interpolation of the texels, with texel centres
//     u = (x + 0.5) / W (periodic in φ) and v = y / (H − 1) (the first and last rows lie on the
//     poles, clamped in θ) — so a sharp change between two rows is a ramp over one row spacing;
//   images smaller than 2×3 are padded by replicating the last column / row (Bitmap::pad_to).
// Importance sampling follows Mitsuba's warp (a Hierarchical2D over luminance × sinθ at the texel
// centres): the density in (u, v) is the bilinear interpolation of d = luminance(texel) · sin(θ_row)
// between texel centres, normalised. A cell between four texel centres (W cells in φ, H − 1 in θ) is
// drawn by its exact integral (the mean of its corners' d), then a point within it from the
// bilinear patch itself (render/distribution.h, sampleLinear). pdf() evaluates that same density, so
// light sampling and MIS stay consistent; radiance / pdf varies within a cell only through colour
// and the ratio sinθ / bilinear sinθ, where a piecewise-constant density left the full ramp of a
// bright texel's bilinear footprint in it.
//
// | parameter (XML) | meaning                                      | default  |
// |-----------------|----------------------------------------------|----------|
// | filename        | lat-long image (EXR, HDR, PNG, … via OIIO)   | required |
// | scale           | radiance multiplier                          | 1        |
// | to_world        | emitter frame (local +y is the image's top)  | identity |
#include <vector>

#include "core/math.h"
#include "core/simd_level.h"
#include "render/distribution.h"
#include "render/envmap_texels.h"

namespace rc {

// The inverse of Mitsuba's lat-long mapping envUv (render/envmap_texels.h), u, v ∈ [0, 1];
// *sinTheta (optional) gets sin(πv).
Vec3 envDirection(float u, float v, float* sinTheta = nullptr);

class EnvmapLight {
 public:
  // pixels: width × height, row-major, top row (θ = 0) first, linear RGB.
  EnvmapLight(int width, int height, const std::vector<Color>& pixels, float scale, const Mat3& toWorld);

  // Radiance arriving along world direction dir.
  Color eval(const Vec3& dirWorld) const;
  // Solid-angle density with which sample() returns dir.
  float pdf(const Vec3& dirWorld) const;
  // eval() and pdf() of one direction, mapped to (u, v) once (the same numbers as the two calls).
  struct Lookup {
    Color radiance{0.0f};
    float pdf = 0.0f;
  };
  Lookup lookup(const Vec3& dirWorld) const;
  // lookup() of n world directions (x[k], y[k], z[k]), added to running sums as LightSampler sums
  // its infinite emitters: radiance[k] += value, pdf[k] += selectProb · density (pdf null: the
  // density is not needed). The same operations as lookup(), so the same numbers bit for bit; one
  // pass over arrays that the compiler vectorises (envmap_light_batch.cpp), run with the widest
  // instruction set up to `level` that the CPU has.
  void lookupAdd(const float* x, const float* y, const float* z, size_t n, float selectProb, float* r, float* g,
                 float* b, float* pdf, SimdLevel level = SimdLevel::Avx512) const;
  // A world direction drawn from the luminance-weighted density, with the radiance and density
  // there (pdf 0 when the map is black: then there is nothing to sample).
  struct Sample {
    Vec3 dir{0, 0, 1};
    Lookup value;
  };
  Sample sample(Vec2 u) const;
  // Luminance averaged over the sphere of directions (for emitter selection by power).
  double meanLuminance() const { return meanLuminance_; }

 private:
  int width_ = 0, height_ = 0;  // after padding
  // Per texel (row-major, top row first): scaled radiance in xyz, the sampling weight
  // luminance · sin(θ_row) in w — one bilinear interpolation gives both.
  std::vector<Vec4> texels_;
  Mat3 toWorld_{1.0f}, toLocal_{1.0f};
  PiecewiseConstant2D cells_;  // the W × (H − 1) cells between texel centres: bands, then cells within one
  // Solid-angle density = interpolated weight × pdfScale_ / sinθ: W·(H − 1) / Σ cell means / 2π².
  float pdfScale_ = 0.0f;
  double meanLuminance_ = 0.0;

  const Vec4& texel(int x, int y) const { return texels_[static_cast<size_t>(y) * width_ + x]; }
  static_assert(sizeof(Vec4) == 4 * sizeof(float), "tables() reads texels_ as an array of floats");
  EnvmapTexels tables() const { return EnvmapTexels{&texels_.data()->x, pdfScale_, width_, height_, toLocal_}; }
};

}  // namespace rc
