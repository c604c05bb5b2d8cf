#pragma once
// The scene's light split in two, so that radiance records carry the part spherical harmonics
// hold and only the rest is light-sampled per pixel sample.
//
// Environment (constant and envmap emitters):
//   L_env(ω) = L_cached(ω) + L_residual(ω),
//   L_cached = each texel t scaled down to luminance ≤ τ (t·min(1, τ/lum t)), constants whole;
//   L_residual = the rest (a sun, a small bright window: compact and bright, which light
//               sampling handles almost perfectly and SH of any practical order does not).
// Both parts are bilinear interpolations of their texels like the envmap itself, so they add up to
// L_env exactly in every direction. A record ray that escapes carries L_cached (visibility comes
// from the record's own rays).
// Area emitters (only with area_cache=true): a record ray that hits one carries its emission,
// and the emitter leaves the residual lights.
// A point whose indirect light comes from records light-samples the residual lights alone
// (residualLights(): area, point and directional lights as before, minus cached area emitters,
// plus L_residual), with the same MIS; every other point (importance-sampled, no indirect light)
// sees all of the scene's light. The sum is the path tracer's estimator of the same integral,
// term by term.
//
// Choice of τ (per envmap, from its histogram over solid angle): a record estimates its incoming
// radiance from M×N uniform hemisphere rays (course notes, "Incoming Radiance Computation"), so
// what it gets wrong is the variance of the cached radiance over its hemisphere. τ is the largest
// threshold at which, for each of the six hemispheres around the map's own axes (not the world's,
// so that the split does not change when the whole scene is turned), that variance stays ≤ κ
// times the square of the brightest hemisphere's mean (κ = env_variance, default 1/3: the relative
// variance that the cosine weight of a diffuse record already has under a uniform sky,
// E[cos²]/E[cos]² − 1 over the uniform hemisphere). Dark hemispheres (ground below a sky) thus
// do not veto the split, and a uniform sky is cached whole. Maps smaller than 2×3 texels have no
// compact part and are cached whole.
#include <memory>
#include <string>
#include <vector>

#include "core/math.h"
#include "render/envmap_light.h"
#include "render/light_sampler.h"
#include "scene/scene.h"

namespace rc {

struct LightSplitSummary {
  bool active = false;         // records carry part of the scene's light
  bool environmentCached = false;  // ... part of the environment
  bool areaCached = false;     // ... the area emitters' emission
  std::string reason;          // why not, when inactive
  float threshold = 0.0f;      // τ (luminance) of the brightest envmap; +inf when cached whole
  double cachedFraction = 0.0; // of the environment's power (luminance over the sphere)
  double sampledFraction = 1.0;
};

class LightSplit {
 public:
  // Environment part when `environment` and the scene has one (κ = maxRelativeVariance); area
  // emitters when `areaEmitters` and the scene has some. Inactive (everything light-sampled as
  // before) when neither applies.
  LightSplit(const Scene& scene, bool environment, float maxRelativeVariance, bool areaEmitters = false);
  LightSplit(const LightSplit&) = delete;
  LightSplit& operator=(const LightSplit&) = delete;

  bool active() const { return summary_.active; }
  const LightSplitSummary& summary() const { return summary_; }
  // L_cached along a world direction: what an escaping record ray carries.
  Color cached(const Vec3& dirWorld) const;
  // What a record ray that found `hit` along dirWorld carries of the emitter there (0 unless
  // area emitters are cached).
  Color cachedEmission(const Hit& hit, const Vec3& dirWorld) const;
  // Lights for points whose indirect light comes from records (valid only when active()).
  const LightSampler& residualLights() const { return *residualLights_; }

 private:
  LightSplitSummary summary_;
  Color cachedConstant_{0.0f};
  std::vector<EnvmapLight> cachedEnvmaps_;
  const Scene* scene_ = nullptr;
  std::vector<Emitter> residualEmitters_;  // the scene's emitters, environment parts replaced
  std::unique_ptr<LightSampler> residualLights_;
};

// τ for one lat-long map (texels row-major, top row first, already scaled): see the file comment.
// +inf when the whole map passes. The hemispheres are the map's own (its to_world left out): a
// scene turned as a whole, envmap included, keeps its split, which world axes would not.
float environmentSplitThreshold(int width, int height, const std::vector<Color>& texels, float maxRelativeVariance);

}  // namespace rc
