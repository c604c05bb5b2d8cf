#pragma once
// The path tracer's batched (wavefront) core: many camera samples advance together one path vertex
// at a time, so each bounce's extension rays go to the BVH as one batched query and each bounce's
// shadow rays as one occlusion query, instead of one Embree call per ray.
//
// Same estimator as pathRadiance (render/path_integrator.h), which stays as the reference: every
// sample draws the same numbers from its own Rng in the same order (light sample, BSDF sample,
// Russian roulette per vertex) and adds the same terms in the same order, so with the same hits a
// sample's radiance is bit-identical to pathRadiance's.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/rng.h"
#include "render/diffuse_shading.h"
#include "render/integrator.h"
#include "render/light_sampler.h"

namespace rc {

// Reusable per-thread buffers of one wave (structure of arrays over the wave's lanes); sized on
// first use and kept, so rendering allocates nothing per sample.
struct PathWave {
  std::vector<Ray> rays;  // per lane: the segment it traces next
  std::vector<Color> radiance, throughput;
  std::vector<Vec3> prevP;
  std::vector<float> eta, prevPdf;
  std::vector<uint8_t> prevDelta;
  std::vector<uint32_t> active, next;  // lanes still extending their path
  std::vector<uint8_t> continues;      // per lane: 1 when this bounce extends its path
  DiffuseGroup diffuse;                // this bounce's diffuse vertices, shaded as one group
  // This bounce's shadow rays and what each adds to its lane if unoccluded.
  std::vector<Ray> shadowRays;
  std::vector<Color> shadowValue;
  std::vector<uint32_t> shadowLane;
  std::vector<uint32_t> shadowOrder;  // the shadow rays in the order they are traced
  std::vector<uint8_t> blocked;       // per traced shadow ray (in shadowOrder)
  std::vector<uint8_t> octants;       // scratch of orderByOctant
  std::vector<Ray> waveRays;  // gathered rays of the active lanes
  std::vector<Hit> waveHits;
  // This bounce's escaped segments: their directions and the environment along them (looked up in
  // one vectorised pass), and per lane the entry of its segment.
  LightSampler::EnvironmentWave escaped;
  std::vector<uint32_t> escapedEntry;
};

// Radiance of `count` camera samples: cameraRays[i] with its first hit cameraHits[i] (already
// traced; read in place, not copied), drawing from rngs[i]; out[i] receives the sample's radiance.
// `query` picks how the batches go to Embree.
void pathRadianceBatch(const RenderContext& ctx, const IntegratorSettings& settings, const Ray* cameraRays,
                       const Hit* cameraHits, Rng* rngs, size_t count, Color* out, PathWave& wave,
                       BatchQuery query = BatchQuery::Packet16);

}  // namespace rc
