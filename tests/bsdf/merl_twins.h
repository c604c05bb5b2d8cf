#pragma once
// The analytic BSDFs of the merl tests and their MERL-format twins (full database resolution,
// tabulated in memory once per process).
#include <map>
#include <string>

#include "bsdf/merl_bsdf.h"
#include "bsdf/merl_tabulate.h"
#include "bsdf_test_util.h"

namespace rc::test {

inline BsdfPtr analyticForTwin(const std::string& name) {
  if (name == "ggx")
    return make("roughconductor", {str("distribution", "ggx"), num("alpha", 0.2),
                                   rgb("eta", 0.2f, 0.9f, 1.1f), rgb("k", 3.9f, 2.4f, 1.6f)});
  if (name == "beckmann") return make("roughconductor", {str("distribution", "beckmann"), num("alpha", 0.3)});
  if (name == "lambert") return make("diffuse", {rgb("reflectance", 0.2f, 0.5f, 0.8f)});
  // Two lobes: a sharp GGX highlight over a diffuse base.
  return make("blendbsdf", {num("weight", 0.4)},
              {make("diffuse", {rgb("reflectance", 0.6f, 0.4f, 0.3f)}),
               make("roughconductor", {str("distribution", "ggx"), num("alpha", 0.08)})});
}

// The merl BSDF of `name` ("ggx", "beckmann", "lambert", "mix" or "retro", the hand-made lobe).
inline BsdfPtr merlTwin(const std::string& name) {
  static std::map<std::string, BsdfPtr> made;
  auto it = made.find(name);
  if (it != made.end()) return it->second;
  BsdfPtr b;
  if (name == "retro") {
    b = makeMerlBsdf(tabulateMerl(RetroReflectiveLobe()));
  } else {
    const BsdfPtr analytic = analyticForTwin(name);
    b = makeMerlBsdf(tabulateMerl(brdfOf(*analytic)));
  }
  made[name] = b;
  return b;
}

}  // namespace rc::test
