#include "cache/cache_params.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace rc {

RcacheParams readRcacheParams(ParamReader& in) {
  RcacheParams p;
  p.a = in.real("a", p.a, 1e-3f, 10.0f);
  p.rays = in.integer("rays", p.rays, 8, 65536);
  p.order = in.integer("order", p.order, 0, 16);
  p.weber = in.real("weber", p.weber, 1e-4f, 10.0f);
  p.adaptive = in.flag("adaptive", p.adaptive);
  p.minAScale = in.real("min_a_scale", p.minAScale, 1e-3f, 1.0f);
  p.gradients = in.flag("gradients", p.gradients);
  p.rMinPx = in.real("rmin", p.rMinPx, 0.01f, 1e6f);
  p.rMaxPx = in.real("rmax", p.rMaxPx, 0.01f, 1e9f);
  // Checked right after rmax is read, so a file's error names rmax's line.
  if (p.rMinPx > p.rMaxPx) throw Error("rcache parameters: rmin must not exceed rmax");
  p.secondaryAScale = in.real("secondary_a_scale", p.secondaryAScale, 1.0f, 100.0f);
  p.secondaryRays = in.integer("secondary_rays", p.secondaryRays, 8, 65536);
  p.secondaryOrder = in.integer("secondary_order", p.secondaryOrder, 0, 16);
  p.cacheDepth = in.integer("cache_depth", p.cacheDepth, 1, 8);
  p.batch = in.integer("batch", p.batch, 1, 1 << 16);
  p.sharePixel = in.flag("share_pixel", p.sharePixel);
  p.lightSamples = in.integer("light_samples", p.lightSamples, 1, 64);
  p.envCache = in.flag("env_cache", p.envCache);
  p.envVariance = in.real("env_variance", p.envVariance, 1e-6f, 1e6f);
  p.areaCache = in.flag("area_cache", p.areaCache);
  p.fallback = in.flag("fallback", p.fallback);
  p.fallbackShare = in.real("fallback_share", p.fallbackShare, 0.0f, 1.0f);
  const std::string split = in.choice("lobe_split", "auto", {"auto", "true", "false"});
  p.lobeSplit = split == "auto"   ? RcacheParams::LobeSplitMode::Auto
                : split == "true" ? RcacheParams::LobeSplitMode::On
                                  : RcacheParams::LobeSplitMode::Off;
  p.costPilot = in.flag("cost_pilot", p.costPilot);
  p.costPilotShare = in.real("cost_pilot_share", p.costPilotShare, 0.0f, 1e6f);
  const std::string frame = in.choice("frame", "auto", {"auto", "world", "record"});
  p.worldFrame = frame != "record";
  p.autoFrame = frame == "auto";
  p.tlMode = in.choice("mode", "radiance", {"radiance", "tl"}) == "tl";
  return p;
}

void hemisphereCells(int rays, int& M, int& N) {
  M = std::max(2, static_cast<int>(std::ceil(std::sqrt(rays / 4.0))));
  N = std::max(4, (rays + M - 1) / M);
}

}  // namespace rc
