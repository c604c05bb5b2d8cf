#include "render/envmap_light.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace rc {

Vec3 envDirection(float u, float v, float* sinTheta) {
  const float theta = v * kPi, phi = u * 2.0f * kPi;
  const float st = std::sin(theta);
  if (sinTheta) *sinTheta = st;
  return Vec3(st * std::sin(phi), std::cos(theta), -st * std::cos(phi));
}

EnvmapLight::EnvmapLight(int width, int height, const std::vector<Color>& pixels, float scale, const Mat3& toWorld)
    : toWorld_(toWorld), toLocal_(glm::inverse(toWorld)) {
  if (width <= 0 || height <= 0 || pixels.size() != static_cast<size_t>(width) * height)
    throw Error("envmap: image not loaded");
  // Pad like Mitsuba's Bitmap::pad_to(2, 3): replicate the last column, then the last row.
  width_ = std::max(width, 2);
  height_ = std::max(height, 3);
  const int W = width_, bands = height_ - 1;
  std::vector<double> rowSin(height_);
  texels_.resize(static_cast<size_t>(width_) * height_);
  for (int y = 0; y < height_; ++y) {
    rowSin[y] = std::sin(kPiD * y / bands);  // θ of texel row y: its centre lies at v = y / (H − 1)
    for (int x = 0; x < width_; ++x) {
      const Color c = pixels[static_cast<size_t>(std::min(y, height - 1)) * width + std::min(x, width - 1)] * scale;
      texels_[static_cast<size_t>(y) * width_ + x] =
          Vec4(c, static_cast<float>(std::max(0.0f, luminance(c)) * rowSin[y]));
    }
  }
  std::vector<double> cellWeights(static_cast<size_t>(W) * bands);
  double total = 0.0, solid = 0.0;
  for (int j = 0; j < bands; ++j) {
    for (int i = 0; i < W; ++i) {
      const int i1 = (i + 1) % W;
      // ∫ of a bilinear function over its cell = the mean of its four corners.
      const double weight =
          0.25 * (double(texel(i, j).w) + texel(i1, j).w + texel(i, j + 1).w + texel(i1, j + 1).w);
      cellWeights[static_cast<size_t>(j) * W + i] = weight;
      total += weight;
    }
    solid += W * 0.5 * (rowSin[j] + rowSin[j + 1]);  // the same rule for sinθ alone
  }
  cells_ = PiecewiseConstant2D(cellWeights, bands, W);
  pdfScale_ = total > 0.0 ? static_cast<float>(W * bands / total / (2.0 * kPiD * kPiD)) : 0.0f;
  meanLuminance_ = solid > 0.0 ? total / solid : 0.0;
}

Color EnvmapLight::eval(const Vec3& dirWorld) const {
  const EnvmapTexels t = tables();
  return Color(t.bilinear(envUv(t.local(dirWorld))));
}

float EnvmapLight::pdf(const Vec3& dirWorld) const { return lookup(dirWorld).pdf; }

EnvmapLight::Lookup EnvmapLight::lookup(const Vec3& dirWorld) const {
  const EnvmapTexels t = tables();
  const Vec3 d = t.local(dirWorld);
  const Vec4 c = t.bilinear(envUv(d));
  return Lookup{Color(c), t.density(c, EnvmapTexels::sinThetaOf(d))};
}

EnvmapLight::Sample EnvmapLight::sample(Vec2 u) const {
  const PiecewiseConstant2D::Cell c = cells_.sample(u.x, u.y);
  const int i = static_cast<int>(c.column), j = static_cast<int>(c.row), i1 = (i + 1) % width_;
  // Within the cell, the bilinear patch of its corners' weights: the offset in θ from the row's
  // linear marginal, then the offset in φ from the line at that θ.
  const float w00 = texel(i, j).w, w10 = texel(i1, j).w, w01 = texel(i, j + 1).w, w11 = texel(i1, j + 1).w;
  const float ty = sampleLinear(c.remappedY, w00 + w10, w01 + w11);
  const float tx = sampleLinear(c.remappedX, w00 + ty * (w01 - w00), w10 + ty * (w11 - w10));
  float uu = (static_cast<float>(i) + tx + 0.5f) / width_;
  if (uu >= 1.0f) uu -= 1.0f;
  const float vv = (static_cast<float>(j) + ty) / (height_ - 1);
  // Radiance and density at the sampled (u, v) directly, as Mitsuba's envmap does: no round trip
  // through the direction's atan2/acos (which agrees up to float rounding).
  float sinTheta;
  const Vec3 dLocal = envDirection(uu, vv, &sinTheta);
  Sample s;
  s.dir = glm::normalize(toWorld_ * dLocal);
  const EnvmapTexels t = tables();
  const Vec4 at = t.bilinear(Vec2(uu, vv));
  s.value = Lookup{Color(at), t.density(at, sinTheta)};
  return s;
}

}  // namespace rc
