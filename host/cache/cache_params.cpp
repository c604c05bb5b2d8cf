#include "cache/cache_params.h"

#include <cmath>
#include <cstdlib>

#include "core/error.h"

namespace rc {

namespace {

Error bad(const std::string& name, const std::string& value, const std::string& why) {
  return Error("rcache parameter '" + name + "' = '" + value + "': " + why);
}

float toFloat(const std::string& name, const std::string& v, float lo, float hi) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(x)) throw bad(name, v, "not a number");
  if (x < lo || x > hi) throw bad(name, v, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<float>(x);
}

int toInt(const std::string& name, const std::string& v, int lo, int hi) {
  char* end = nullptr;
  const long x = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0') throw bad(name, v, "not an integer");
  if (x < lo || x > hi) throw bad(name, v, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<int>(x);
}

bool toBool(const std::string& name, const std::string& v) {
  if (v == "true" || v == "1" || v == "on") return true;
  if (v == "false" || v == "0" || v == "off") return false;
  throw bad(name, v, "must be true or false");
}

}  // namespace

bool isIntegratorParamName(const std::string& name) {
  static const char* const kNames[] = {"max_depth", "rr_depth", "hide_emitters", "a", "rays", "order", "weber",
                                       "adaptive", "min_a_scale", "gradients", "rmin", "rmax", "secondary_a_scale",
                                       "secondary_rays", "secondary_order", "cache_depth", "batch", "frame", "mode", "share_pixel", "light_samples",
                                       "env_cache", "env_variance", "area_cache", "fallback", "fallback_share"};
  for (const char* n : kNames)
    if (name == n) return true;
  return false;
}

RcacheParams parseRcacheParams(const std::map<std::string, std::string>& params) {
  RcacheParams p;
  for (const auto& [name, v] : params) {
    // Parameters shared with the path integrator are read by the scene loader, not here.
    if (name == "max_depth" || name == "rr_depth" || name == "hide_emitters") continue;
    if (name == "a") p.a = toFloat(name, v, 1e-3f, 10.0f);
    else if (name == "rays") p.rays = toInt(name, v, 8, 65536);
    else if (name == "order") p.order = toInt(name, v, 0, 16);
    else if (name == "weber") p.weber = toFloat(name, v, 1e-4f, 10.0f);
    else if (name == "adaptive") p.adaptive = toBool(name, v);
    else if (name == "min_a_scale") p.minAScale = toFloat(name, v, 1e-3f, 1.0f);
    else if (name == "gradients") p.gradients = toBool(name, v);
    else if (name == "rmin") p.rMinPx = toFloat(name, v, 0.01f, 1e6f);
    else if (name == "rmax") p.rMaxPx = toFloat(name, v, 0.01f, 1e9f);
    else if (name == "secondary_a_scale") p.secondaryAScale = toFloat(name, v, 1.0f, 100.0f);
    else if (name == "secondary_rays") p.secondaryRays = toInt(name, v, 8, 65536);
    else if (name == "secondary_order") p.secondaryOrder = toInt(name, v, 0, 16);
    else if (name == "cache_depth") p.cacheDepth = toInt(name, v, 1, 8);
    else if (name == "batch") p.batch = toInt(name, v, 1, 1 << 16);
    else if (name == "share_pixel") p.sharePixel = toBool(name, v);
    else if (name == "light_samples") p.lightSamples = toInt(name, v, 1, 64);
    else if (name == "env_cache") p.envCache = toBool(name, v);
    else if (name == "env_variance") p.envVariance = toFloat(name, v, 1e-6f, 1e6f);
    else if (name == "area_cache") p.areaCache = toBool(name, v);
    else if (name == "fallback") p.fallback = toBool(name, v);
    else if (name == "fallback_share") p.fallbackShare = toFloat(name, v, 0.0f, 1.0f);
    else if (name == "frame") {
      if (v == "auto") p.worldFrame = p.autoFrame = true;
      else if (v == "world") p.worldFrame = true, p.autoFrame = false;
      else if (v == "record") p.worldFrame = p.autoFrame = false;
      else throw bad(name, v, "must be auto, world or record");
    } else if (name == "mode") {
      if (v == "radiance") p.tlMode = false;
      else if (v == "tl") p.tlMode = true;
      else throw bad(name, v, "must be radiance or tl");
    } else {
      throw Error("rcache parameter '" + name + "' is unknown (known: a, rays, order, weber, adaptive, min_a_scale, "
                  "gradients, rmin, rmax, secondary_a_scale, secondary_rays, secondary_order, cache_depth, batch, frame, mode, share_pixel, light_samples, "
                  "env_cache, env_variance, area_cache, fallback, fallback_share)");
    }
  }
  if (p.rMinPx > p.rMaxPx) throw Error("rcache parameters: rmin must not exceed rmax");
  return p;
}

void hemisphereCells(int rays, int& M, int& N) {
  M = std::max(2, static_cast<int>(std::ceil(std::sqrt(rays / 4.0))));
  N = std::max(4, (rays + M - 1) / M);
}

}  // namespace rc
