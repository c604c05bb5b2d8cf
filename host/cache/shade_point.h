#pragma once
// A surface point to be shaded by the cache engine: the hit, its (possibly flipped) shading
// frame, the viewing direction, and where it sits on the path (depth for max_depth, level =
// number of diffuse/glossy vertices before it, which selects the cache and its accuracy).
#include <cstdint>

#include "core/frame.h"
#include "core/parallel_array.h"
#include "core/rng.h"
#include "geometry/accel.h"
#include "geometry/shading_frame.h"

namespace rc {

struct ShadePoint {
  Hit hit;
  Frame frame;           // shading frame; for two-sided BSDFs seen from behind, flipped to the viewer
  // The hit's own frame (flipped with `frame`): records are placed, oriented and looked up in it;
  // it differs from `frame` where a normal or bump map turns the shading frame.
  Frame geometryFrame;
  Vec3 wo{0, 0, 1};      // toward the viewer, local frame
  int depth = 1;         // path segments from the camera (camera hit = 1, Mitsuba's depth)
  int level = 0;         // diffuse/glossy vertices before this point
  uint64_t seed = 0;     // this point's RNG stream (Rng(seed, 1)), independent of scheduling
  int pixel = -1;        // camera pixel it came from (primary points), for AOVs
  // Light samples this point's direct light took beside one BSDF sample: the MIS weight of the
  // emitter its continuation ray hits (CacheEngine::continuePaths).
  int lightSamples = 1;
  // Primary points of a low-discrepancy pixel sample: the sample's unused Sobol dimensions
  // [ldDim, Rng::kPixelLowDiscrepancyDims) serve this point's own sampling; ldDim = 0: none.
  uint32_t ldSeed = 0, ldIndex = 0, ldDim = 0;
  bool active = false;   // false: nothing to shade (miss, no BSDF, back of a one-sided BSDF)
};

// Read-only points of a batch, held in a std::vector or a ParallelArray.
using PointView = ArrayView<ShadePoint>;

// The RNG of a shade point's sampling decisions, stream `stream`: PCG, after the rest of the
// pixel sample's low-discrepancy dimensions where the point has them.
inline Rng shadePointRng(const ShadePoint& sp, uint64_t stream) {
  Rng rng(sp.seed, stream);
  if (sp.ldDim != 0) rng.useLowDiscrepancy(sp.ldSeed, sp.ldIndex, Rng::kPixelLowDiscrepancyDims, sp.ldDim);
  return rng;
}

// Hands the unused low-discrepancy dimensions of `rng` (a pixel sample's) on to `sp`.
inline void continueLowDiscrepancy(ShadePoint& sp, const Rng& rng) {
  if (rng.lowDiscrepancyDim() >= rng.lowDiscrepancyDims()) return;
  sp.ldSeed = rng.lowDiscrepancySeed();
  sp.ldIndex = rng.lowDiscrepancyIndex();
  sp.ldDim = rng.lowDiscrepancyDim();
}

// The BSDF at a shade point (geometry/shading_frame.h; both of its frames mirrored alike).
inline const Bsdf& bsdfAt(const Bsdf& material, const ShadePoint& sp, BsdfPtr& holder) {
  return bsdfAt(material, sp.hit, sp.frame, sp.geometryFrame.n, holder);
}

// Builds the shade point of a ray's hit (dir = ray direction, world).
// `material`: the hit's BSDF where it may perturb the frame (normalmap, bumpmap), else null.
inline ShadePoint makeShadePoint(const Hit& hit, const Vec3& dir, int depth, int level, uint64_t seed,
                                 bool twoSided, const Bsdf* material = nullptr) {
  ShadePoint sp;
  sp.hit = hit;
  sp.depth = depth;
  sp.level = level;
  sp.seed = seed;
  if (!hit.valid() || hit.bsdf < 0) return sp;
  // Records are looked up at the hit's position; the BRDF meets their radiance in this frame.
  sp.geometryFrame = hit.frame();
  sp.frame = material ? shadingFrame(*material, hit, -dir) : sp.geometryFrame;
  sp.wo = sp.frame.toLocal(-dir);
  if (sp.wo.z <= 0.0f && twoSided) {
    // Mirror the frame to the viewer's side (still right-handed: t × (−b) = −n).
    const auto mirror = [](const Frame& f) { return Frame(f.t, -f.b, -f.n); };
    sp.frame = mirror(sp.frame);
    sp.geometryFrame = mirror(sp.geometryFrame);
    sp.wo = sp.frame.toLocal(-dir);
  }
  sp.active = true;
  return sp;
}

}  // namespace rc
