// Measurements for bench/RESULTS.md ("BRDF tables"): build/bench/rcache-bench-brdf-tables.
// Prints markdown rows: precompute time per material at order 10, automatic orders per
// roughness, and cache-hit load time.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "brdf/material_plan.h"
#include "brdf/order_selection.h"
#include "bsdf/bsdf_factory.h"
#include "common/property_builders.h"
#include "core/parallel.h"

namespace rc {
namespace {

Property prop(double v) { return test::floatProp(v); }
Property prop(const std::string& s) { return test::stringProp(s); }

BsdfPtr make(const std::string& type, const std::string& dist, double au, double av, const std::string& id) {
  Properties props;
  props.pluginType = type;
  if (!dist.empty()) props.set("distribution", prop(dist));
  if (au > 0 && av > 0 && au != av) {
    props.set("alpha_u", prop(au));
    props.set("alpha_v", prop(av));
  } else if (au > 0) {
    props.set("alpha", prop(au));
  }
  return createBsdf(props, {}, id);
}

void precomputeOrdersAndCache() {
  std::printf("threads: %d\n", threadCount());
  const std::string dir = "/tmp/rc_brdf_bench";
  std::filesystem::remove_all(dir);
  std::vector<BsdfPtr> scene;
  for (const char* d : {"ggx", "beckmann"})
    for (double a : {0.05, 0.1, 0.2, 0.3, 0.5, 1.0})
      scene.push_back(make("roughconductor", d, a, a, std::string(d) + " α=" + std::to_string(a).substr(0, 4)));
  scene.push_back(make("roughplastic", "ggx", 0.2, 0.2, "roughplastic ggx α=0.2"));
  scene.push_back(make("roughconductor", "ggx", 0.2, 0.5, "aniso ggx α=0.2/0.5"));
  scene.push_back(make("diffuse", "", 0, 0, "diffuse"));

  std::printf("\n| material | table | order | build ms (order 10, cold) | cache-hit load ms |\n|---|---|---|---|---|\n");
  BrdfTableOptions o;
  o.cacheDir = dir;
  o.orderOverride = 10;
  BrdfTableSet cold, warm;
  cold.build(scene, o);
  warm.build(scene, o);
  for (size_t m = 0; m < scene.size(); ++m) {
    const MaterialPlan& c = cold.plans()[m];
    const MaterialPlan& w = warm.plans()[m];
    std::printf("| %s | %s | %d | %.1f | %.2f%s |\n", c.name.c_str(),
                c.tableKind == 0 ? "1-D T=64" : "2-D S=32", c.shOrder, c.tableMs, w.tableMs,
                w.tableCacheHit ? "" : " (miss!)");
  }
  std::printf("total cold %.1f ms, warm %.1f ms\n", cold.totalMs(), warm.totalMs());

  std::printf("\n| distribution | α | tol 10%%, θ_o≤60° (default) | tol 5%%, θ_o≤60° | tol 10%%, θ_o≤80° | tol 10%%, θ_o≤90° | worst e at order 10 (θ_o≤60°) | plan ms |\n|---|---|---|---|---|---|---|---|\n");
  for (size_t m = 0; m < 12; ++m) {
    const auto t0 = std::chrono::steady_clock::now();
    const OrderChoice def = selectShOrder(*scene[m], 0.10, 16, LobeQuadrature{}, 60.0);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const OrderChoice tight = selectShOrder(*scene[m], 0.05, 16, LobeQuadrature{}, 60.0);
    const OrderChoice wide = selectShOrder(*scene[m], 0.10, 16, LobeQuadrature{}, 80.0);
    const OrderChoice all = selectShOrder(*scene[m], 0.10, 16, LobeQuadrature{}, 90.0);
    auto s = [](const OrderChoice& c) { return c.order ? std::to_string(c.order) : std::string("IS"); };
    std::printf("| %s | %.2f | %s | %s | %s | %s | %.3f | %.1f |\n", m < 6 ? "ggx" : "beckmann",
                std::vector<double>{0.05, 0.1, 0.2, 0.3, 0.5, 1.0}[m % 6], s(def).c_str(), s(tight).c_str(),
                s(wide).c_str(), s(all).c_str(), def.worstError[9], ms);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rc

int main() {
  rc::precomputeOrdersAndCache();
  return 0;
}
