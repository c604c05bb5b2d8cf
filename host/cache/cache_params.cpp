#include "cache/cache_params.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace rc {

namespace {

// A record ray count: 0 (the default) leaves `rays` at its base, to follow the sample budget
// (cache/budget_params.h); an explicit count of 8 or more is used as given.
void readRayCount(ParamReader& in, const char* name, int& rays, bool& followsBudget) {
  const int value = in.integer(name, 0, 0, 65536);
  if (value == 0) return;
  if (value < 8)
    throw Error(std::string("parameter '") + name + "' = '" + std::to_string(value) +
                "': must be 0 (automatic: follows the sample budget) or 8..65536");
  rays = value;
  followsBudget = false;
}

// A real that follows the budget unless given (the fallback below any valid value marks "not
// given": ParamReader range-checks only given values).
void readFollowing(ParamReader& in, const char* name, float lo, float hi, float& value, bool& followsBudget) {
  const float given = in.real(name, lo - 1.0f, lo, hi);
  if (given < lo) return;
  value = given;
  followsBudget = false;
}

}  // namespace

RcacheParams readRcacheParams(ParamReader& in) {
  RcacheParams p;
  readFollowing(in, "a", 1e-3f, 10.0f, p.a, p.follow.a);
  readRayCount(in, "rays", p.rays, p.follow.rays);
  p.order = in.integer("order", p.order, 0, 16);
  p.weber = in.real("weber", p.weber, 1e-4f, 10.0f);
  p.adaptive = in.flag("adaptive", p.adaptive);
  p.minAScale = in.real("min_a_scale", p.minAScale, 1e-3f, 1.0f);
  p.gradients = in.flag("gradients", p.gradients);
  readFollowing(in, "rmin", 0.01f, 1e6f, p.rMinPx, p.follow.rMin);
  readFollowing(in, "rmax", 0.01f, 1e9f, p.rMaxPx, p.follow.rMax);
  // Checked right after rmax is read, so a file's error names rmax's line.
  if (p.rMinPx > p.rMaxPx) throw Error("rcache parameters: rmin must not exceed rmax");
  p.secondaryAScale = in.real("secondary_a_scale", p.secondaryAScale, 1.0f, 100.0f);
  readRayCount(in, "secondary_rays", p.secondaryRays, p.follow.secondaryRays);
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
  p.fillPayoff = in.flag("fill_payoff", p.fillPayoff);
  const std::string frame = in.choice("frame", "auto", {"auto", "world", "record"});
  p.worldFrame = frame != "record";
  p.autoFrame = frame == "auto";
  p.tlMode = in.choice("mode", "radiance", {"radiance", "tl"}) == "tl";
  if (!in.flag("follow_budget", true)) p.follow = RcacheParams::FollowBudget{false, false, false, false, false};
  return p;
}

void hemisphereCells(int rays, int& M, int& N) {
  M = std::max(2, static_cast<int>(std::ceil(std::sqrt(rays / 4.0))));
  N = std::max(4, (rays + M - 1) / M);
}

}  // namespace rc
