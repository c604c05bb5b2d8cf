#include "cache/budget_params.h"

#include <algorithm>
#include <cmath>

namespace rc {

namespace {

double budgetGrowth(int spp) { return double(std::clamp(spp, kBudgetMinSpp, kBudgetMaxSpp)) / kBudgetBaseSpp; }

}  // namespace

int budgetRays(int base, int spp) {
  const double rays = std::round(base * std::sqrt(budgetGrowth(spp)));
  return static_cast<int>(std::min(double(std::max(base, kBudgetMaxRays)), rays));
}

float budgetRadiusScale(int spp) { return static_cast<float>(std::pow(budgetGrowth(spp), -0.25)); }

RcacheParams paramsForBudget(const RcacheParams& params, int spp) {
  RcacheParams p = params;
  if (p.follow.rays) p.rays = budgetRays(p.rays, spp);
  if (p.follow.secondaryRays) p.secondaryRays = budgetRays(p.secondaryRays, spp);
  const float scale = budgetRadiusScale(spp);
  if (p.follow.a) p.a *= scale;
  if (p.follow.rMin) p.rMinPx *= scale;
  if (p.follow.rMax) p.rMaxPx = std::max(p.rMaxPx * scale, p.rMinPx);
  // A grown r_min must not pass a given r_max.
  if (p.follow.rMin) p.rMinPx = std::min(p.rMinPx, p.rMaxPx);
  return p;
}

}  // namespace rc
