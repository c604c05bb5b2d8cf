#pragma once
// The primary hits of film positions: camera ray, shade point and the emission the camera sees
// there. Shared by the cache fill (pixel centres) and the final pass (jittered samples).
#include <cstdint>
#include <vector>

#include "cache/cache_engine.h"
#include "cache/shade_point.h"
#include "render/camera.h"
#include "render/integrator.h"

namespace rc {

struct Primary {
  ShadePoint sp;
  Vec2 filmPos;
  Color Le{0.0f};  // emission seen directly (emitter or environment), 0 when hidden
};

class PrimaryHits {
 public:
  PrimaryHits(const RenderContext& ctx, const CacheEngine& engine, const CameraModel& camera, int maxDepth,
              bool hideEmitters)
      : ctx_(ctx), engine_(engine), camera_(camera), maxDepth_(maxDepth), hideEmitters_(hideEmitters) {}

  // The primary hit of one film position, from its camera ray and the ray's hit.
  Primary of(const Vec2& filmPos, int pixel, uint64_t sampleSeed, const Ray& ray, const Hit& hit) const;
  // Primary hits of a set of film positions (camera rays traced as coherent streams, in parallel).
  void trace(const std::vector<Vec2>& filmPos, const std::vector<int>& pixel, const std::vector<uint64_t>& seeds,
             std::vector<Primary>& out) const;

 private:
  const RenderContext& ctx_;
  const CacheEngine& engine_;
  const CameraModel& camera_;
  int maxDepth_;
  bool hideEmitters_;
};

}  // namespace rc
