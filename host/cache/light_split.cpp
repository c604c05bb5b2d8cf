#include "cache/light_split.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/direct_light.h"

namespace rc {

namespace {

// Bisection steps on log τ between the map's smallest and largest positive luminance: 2^-30 of
// that range, far below anything the statistics resolve.
constexpr int kThresholdSteps = 30;

// The part of texel t a record carries under threshold tau.
Color cachedTexel(const Color& t, float tau) {
  const float l = luminance(t);
  return l > tau ? t * (tau / l) : t;
}

// Texel centre directions in the map's own frame (Mitsuba's lat-long: u = (x+½)/W, v = y/(H−1))
// and the solid angle of each texel's cell (its row's θ band, clipped at the poles, times 2π/W).
struct TexelGeometry {
  std::vector<Vec3> dir;
  std::vector<double> solidAngle;
};
TexelGeometry texelGeometry(int W, int H) {
  TexelGeometry g;
  g.dir.resize(static_cast<size_t>(W) * H);
  g.solidAngle.resize(g.dir.size());
  const double dTheta = kPiD / (H - 1);
  for (int y = 0; y < H; ++y) {
    const double a = std::max(0.0, (y - 0.5) * dTheta), b = std::min(kPiD, (y + 0.5) * dTheta);
    const double omega = 2.0 * kPiD / W * (std::cos(a) - std::cos(b));
    for (int x = 0; x < W; ++x) {
      const size_t i = static_cast<size_t>(y) * W + x;
      g.dir[i] = envDirection((x + 0.5f) / W, static_cast<float>(y) / (H - 1));
      g.solidAngle[i] = omega;
    }
  }
  return g;
}

}  // namespace

float environmentSplitThreshold(int W, int H, const std::vector<Color>& texels, float maxRelativeVariance) {
  if (W < 2 || H < 3 || texels.size() != static_cast<size_t>(W) * H) return INFINITY;
  const TexelGeometry g = texelGeometry(W, H);
  const size_t n = texels.size();
  static const Vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  // The hemispheres a texel lies in (at most three: one of each opposite pair) and each
  // hemisphere's solid angle do not depend on τ: found once, not in each of the bisection's
  // passes (which then add the same terms in the same order: the same τ).
  struct Texel {
    float lum;
    uint8_t hemispheres = 0;
    uint8_t hemisphere[3] = {};
  };
  std::vector<Texel> tx(n);
  double w[6] = {};
  float lo = INFINITY, hi = 0.0f;
  for (size_t i = 0; i < n; ++i) {
    Texel& t = tx[i];
    t.lum = std::max(0.0f, luminance(texels[i]));
    if (t.lum > 0.0f) lo = std::min(lo, t.lum), hi = std::max(hi, t.lum);
    for (int h = 0; h < 6; ++h)
      if (glm::dot(g.dir[i], kAxes[h]) > 0.0f) {
        w[h] += g.solidAngle[i];
        t.hemisphere[t.hemispheres++] = static_cast<uint8_t>(h);
      }
  }
  if (!(hi > 0.0f)) return INFINITY;
  // Whether the map clamped at tau keeps every hemisphere's variance within κ·(brightest mean)².
  auto passes = [&](float tau) {
    double m[6] = {}, q[6] = {};
    for (size_t i = 0; i < n; ++i) {
      const double l = std::min(tx[i].lum, tau), om = g.solidAngle[i];
      for (uint8_t k = 0; k < tx[i].hemispheres; ++k) {
        const int h = tx[i].hemisphere[k];
        m[h] += om * l, q[h] += om * l * l;
      }
    }
    double brightest = 0.0, worstVar = 0.0;
    for (int h = 0; h < 6; ++h) {
      if (!(w[h] > 0.0)) continue;
      const double mean = m[h] / w[h];
      brightest = std::max(brightest, mean);
      worstVar = std::max(worstVar, q[h] / w[h] - mean * mean);
    }
    return worstVar <= maxRelativeVariance * brightest * brightest;
  };
  if (passes(hi)) return INFINITY;
  // Clamped at the smallest positive luminance the map is nearly constant; bisect in log τ.
  double a = std::log(static_cast<double>(lo)), b = std::log(static_cast<double>(hi));
  if (!passes(lo)) return lo;
  for (int s = 0; s < kThresholdSteps; ++s) {
    const double mid = 0.5 * (a + b);
    (passes(static_cast<float>(std::exp(mid))) ? a : b) = mid;
  }
  return static_cast<float>(std::exp(a));
}

LightSplit::LightSplit(const Scene& scene, bool environment, float maxRelativeVariance, bool areaEmitters)
    : scene_(&scene) {
  bool hasEnvironment = false, hasArea = false;
  for (const Emitter& e : scene.emitters) {
    hasEnvironment |= e.type == EmitterType::Constant || e.type == EmitterType::Envmap;
    hasArea |= e.type == EmitterType::Area;
  }
  environment &= hasEnvironment;
  summary_.environmentCached = environment;
  summary_.areaCached = areaEmitters && hasArea;
  if (!environment) summary_.reason = !hasEnvironment ? "no environment emitter" : "disabled";
  if (!environment && !summary_.areaCached) return;
  residualEmitters_ = scene.emitters;
  double cachedPower = 0.0, totalPower = 0.0;
  summary_.threshold = INFINITY;
  bool anyThreshold = false;
  for (Emitter& e : residualEmitters_) {
    if (e.type == EmitterType::Area && summary_.areaCached) e.radiance = Color(0.0f);
    if (!environment) continue;
    if (e.type == EmitterType::Constant) {
      // A constant is as smooth as light gets: records carry all of it.
      const double p = 4.0 * kPiD * luminance(e.radiance);
      cachedPower += p;
      totalPower += p;
      cachedConstant_ += e.radiance;
      e.radiance = Color(0.0f);
      continue;
    }
    if (e.type != EmitterType::Envmap) continue;
    const int W = e.envWidth, H = e.envHeight;
    std::vector<Color> scaled(e.envPixels.size());
    for (size_t i = 0; i < scaled.size(); ++i) scaled[i] = e.envPixels[i] * e.scale;
    const Mat3 toWorld(e.toWorld);
    const float tau = environmentSplitThreshold(W, H, scaled, maxRelativeVariance);
    std::vector<Color> cachedTexels(scaled.size()), residual(scaled.size());
    for (size_t i = 0; i < scaled.size(); ++i) {
      cachedTexels[i] = cachedTexel(scaled[i], tau);
      residual[i] = scaled[i] - cachedTexels[i];
    }
    if (W >= 2 && H >= 3) {
      const TexelGeometry g = texelGeometry(W, H);
      for (size_t i = 0; i < scaled.size(); ++i) {
        cachedPower += g.solidAngle[i] * std::max(0.0f, luminance(cachedTexels[i]));
        totalPower += g.solidAngle[i] * std::max(0.0f, luminance(scaled[i]));
      }
    } else {
      cachedPower += 1.0;
      totalPower += 1.0;
    }
    cachedEnvmaps_.emplace_back(W, H, cachedTexels, 1.0f, toWorld);
    // The residual emitter keeps its scale: its texels are stored unscaled like the scene's.
    for (Color& r : residual) r = e.scale != 0.0f ? r / e.scale : Color(0.0f);
    e.envPixels = std::move(residual);
    if (std::isfinite(tau)) summary_.threshold = anyThreshold ? std::max(summary_.threshold, tau) : tau;
    anyThreshold |= std::isfinite(tau);
  }
  residualLights_ = std::make_unique<LightSampler>(scene, residualEmitters_);
  summary_.active = true;
  summary_.cachedFraction = totalPower > 0.0 ? cachedPower / totalPower : environment ? 1.0 : 0.0;
  summary_.sampledFraction = 1.0 - summary_.cachedFraction;
}

Color LightSplit::cachedEmission(const Hit& hit, const Vec3& dirWorld) const {
  return summary_.areaCached ? emitted(*scene_, hit, -dirWorld) : Color(0.0f);
}

Color LightSplit::cached(const Vec3& dirWorld) const {
  Color L = cachedConstant_;
  for (const EnvmapLight& e : cachedEnvmaps_) L += e.eval(dirWorld);
  return L;
}

}  // namespace rc
