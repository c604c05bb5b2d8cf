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
  texels_.resize(static_cast<size_t>(width_) * height_);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x)
      texels_[static_cast<size_t>(y) * width_ + x] =
          pixels[static_cast<size_t>(std::min(y, height - 1)) * width + std::min(x, width - 1)] * scale;

  const int W = width_, bands = height_ - 1;
  const double dTheta = kPiD / bands;
  std::vector<double> rowWeights(bands, 0.0);
  std::vector<double> cellWeights(static_cast<size_t>(W) * bands);
  double total = 0.0, solid = 0.0;
  for (int j = 0; j < bands; ++j) {
    // Mean sinθ over the band: ∫ sinθ dθ / Δθ.
    const double meanSin = (std::cos(j * dTheta) - std::cos((j + 1) * dTheta)) / dTheta;
    for (int i = 0; i < W; ++i) {
      const int i1 = (i + 1) % W;
      // ∫ of a bilinear function over its cell = the mean of its four corners.
      const double lum = 0.25 * (std::max(0.0f, luminance(texel(i, j))) + std::max(0.0f, luminance(texel(i1, j))) +
                                 std::max(0.0f, luminance(texel(i, j + 1))) + std::max(0.0f, luminance(texel(i1, j + 1))));
      const double weight = lum * meanSin;
      cellWeights[static_cast<size_t>(j) * W + i] = weight;
      rowWeights[j] += weight;
    }
    total += rowWeights[j];
    solid += W * meanSin;
  }
  cells_ = PiecewiseConstant2D(cellWeights, bands, W);
  cellPdfUv_.assign(cellWeights.size(), 0.0);
  if (total > 0.0)
    for (size_t k = 0; k < cellWeights.size(); ++k) cellPdfUv_[k] = cellWeights[k] / total * W * bands;
  meanLuminance_ = solid > 0.0 ? total / solid : 0.0;
}

Color EnvmapLight::eval(const Vec3& dirWorld) const {
  const EnvmapTexels t = tables();
  return t.bilinear(envUv(t.local(dirWorld)));
}

float EnvmapLight::pdf(const Vec3& dirWorld) const {
  const EnvmapTexels t = tables();
  const Vec3 d = t.local(dirWorld);
  return t.pdf(d, envUv(d));
}

EnvmapLight::Lookup EnvmapLight::lookup(const Vec3& dirWorld) const {
  const EnvmapTexels t = tables();
  const Vec3 d = t.local(dirWorld);
  const Vec2 uv = envUv(d);
  return Lookup{t.bilinear(uv), t.pdf(d, uv)};
}

EnvmapLight::Sample EnvmapLight::sample(Vec2 u) const {
  const PiecewiseConstant2D::Cell c = cells_.sample(u.x, u.y);
  const size_t i = c.column, j = c.row;
  float uu = (static_cast<float>(i) + c.remappedX + 0.5f) / width_;
  if (uu >= 1.0f) uu -= 1.0f;
  const float vv = (static_cast<float>(j) + c.remappedY) / (height_ - 1);
  // Radiance and density at the sampled (u, v) and cell directly, as Mitsuba's envmap does: no
  // round trip through the direction's atan2/acos (which agrees up to float rounding).
  float sinTheta;
  const Vec3 dLocal = envDirection(uu, vv, &sinTheta);
  Sample s;
  s.dir = glm::normalize(toWorld_ * dLocal);
  if (!(sinTheta > 0.0f)) return s;  // pdf 0: the poles carry no solid angle
  s.value.radiance = tables().bilinear(Vec2(uu, vv));
  s.value.pdf = static_cast<float>(cellPdfUv_[j * width_ + i] / (2.0 * kPiD * kPiD * sinTheta));
  return s;
}

}  // namespace rc
