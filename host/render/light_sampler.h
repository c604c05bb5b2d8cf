#pragma once
// Light sampling for next-event estimation over every emitter of the scene: area lights on triangle
// meshes (emitter picked by power, triangle by area, uniform point on it) and on analytic spheres
// (uniform in the visible cone), point, directional, constant and envmap (importance sampled by
// luminance·sinθ on the lat-long image, Mitsuba orientation with to_world).
#include <memory>
#include <optional>
#include <vector>

#include "core/math.h"
#include "geometry/accel.h"
#include "scene/scene.h"

namespace rc {

struct LightSample {
  Vec3 wi{0, 0, 1};       // world direction from the shading point toward the light (unit)
  float dist = INFINITY;  // distance to the sampled light point (inf for infinite lights)
  Color radiance{0.0f};   // Le / pdf (selection probability included): multiply by f·cos, weight by MIS
  float pdf = 0.0f;       // solid-angle pdf incl. emitter selection; 0 for delta lights
  bool delta = false;     // point or directional
  Vec3 lightPoint{0.0f};  // sampled emitter point (finite lights), for shadow rays
  Vec3 lightNormal{0.0f}; // its geometric normal (area lights), zero otherwise
};

class LightSampler {
 public:
  explicit LightSampler(const Scene& scene);
  // The scene's shapes with `emitters` (same count and order as scene.emitters, outliving the
  // sampler) in place of its emitters: a sampler for a part of the scene's light (rcache's
  // residual environment, cache/light_split.h).
  LightSampler(const Scene& scene, const std::vector<Emitter>& emitters);
  ~LightSampler();
  LightSampler(const LightSampler&) = delete;
  LightSampler& operator=(const LightSampler&) = delete;

  // Samples a light as seen from point p. u: 2-D sample on the emitter, uLight: picks the emitter.
  // Empty when the scene has no emitter or the sample carries no energy (back side of an area light).
  std::optional<LightSample> sample(const Vec3& p, Vec2 u, float uLight) const;
  // Solid-angle pdf (selection included) with which sample() from `from` returns the emitter point
  // `lightHit` (an area emitter hit). 0 when lightHit is not on an emitter.
  float pdf(const Hit& lightHit, const Vec3& from) const;

  // Radiance arriving along world direction `dir` from infinitely far (constant + envmap); 0 if none.
  Color environment(const Vec3& dir) const;
  // Solid-angle pdf (selection included) with which sample() returns direction dir from an infinite emitter.
  float environmentPdf(const Vec3& dir) const;
  // Both at once (each envmap's image looked up once): the same numbers as the two calls.
  struct EnvironmentLookup {
    Color radiance{0.0f};
    float pdf = 0.0f;
  };
  EnvironmentLookup environmentLookup(const Vec3& dir) const;
  // Directions and what the environment sends along them, as arrays (one entry per escaped ray of
  // a wave), so that the envmaps are looked up in one vectorised pass (EnvmapLight::lookupAdd).
  struct EnvironmentWave {
    std::vector<float> x, y, z;       // world directions (unit)
    std::vector<float> r, g, b, pdf;  // radiance and density, as environmentLookup gives them
    void fit(size_t n);               // every array holds at least n entries (kept between waves)
    EnvironmentLookup at(size_t k) const { return EnvironmentLookup{Color(r[k], g[k], b[k]), pdf[k]}; }
  };
  // environmentLookup() of the first n directions of `wave`, bit for bit (the densities only when
  // withPdf, else left 0: environment() alone).
  void environmentLookups(EnvironmentWave& wave, size_t n, bool withPdf) const;
  bool hasEnvironment() const;
  // An upper bound of the solid angle the emitters subtend from p (the area emitters' bounding
  // spheres; 4π with an infinite emitter, from inside a bound, or with more than 16 emitters). Lets a caller skip the BSDF
  // strategy of MIS where the lights are small: there light sampling alone is nearly optimal.
  float solidAngleBound(const Vec3& p) const;

  // The emitters this sampler samples (the scene's, or the replacement it was built with).
  const std::vector<Emitter>& emitters() const;
  bool empty() const;
  size_t emitterCount() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rc
