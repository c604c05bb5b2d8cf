// BRDF×cos tables of the merl BSDF: projected from the measured data by the same machinery and the
// same bandwidth rule as the analytic BSDFs, cached on disk by the file's content.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "brdf/material_plan.h"
#include "bsdf/merl_twins.h"

namespace rc {
namespace {

namespace fs = std::filesystem;

struct ScratchDir {
  std::string path;
  ScratchDir() {
    char tmpl[] = "/tmp/rc_merl_table_XXXXXX";
    path = mkdtemp(tmpl);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

BrdfTableOptions options(const std::string& dir) {
  BrdfTableOptions o;
  o.cacheDir = dir;
  o.isotropicRes = 16;
  o.notice = [](const std::string&) {};
  return o;
}

// The twin's technique is its analytic BSDF's, its order equals the analytic one's within one (the
// plan's worst error is a QMC estimate near the tolerance), and at a common order its table equals
// the analytic table within 1% of the table's norm (measured 0.27–0.34%: the table discretisation plus both projections' quadrature noise).
TEST(MerlTables, TwinGetsTheOrderAndTableOfItsAnalyticBsdf) {
  ScratchDir dir;
  for (const char* name : {"ggx", "beckmann", "mix"}) {
    const BsdfPtr analytic = test::analyticForTwin(name), twin = test::merlTwin(name);
    BrdfTableSet planned;
    planned.build({analytic, twin}, options(dir.path));
    const MaterialPlan &pa = planned.plans()[0], &pt = planned.plans()[1];
    // The sharp ones (GGX α = 0.2, the mix's α = 0.08) exceed order 16 and go to importance sampling
    // as their analytic BSDFs do.
    EXPECT_EQ(pt.technique, pa.technique) << name;
    if (std::string(name) == "beckmann") EXPECT_EQ(pt.technique, Technique::RadianceCache);
    EXPECT_LE(std::abs(pa.shOrder - pt.shOrder), 1) << name << " analytic " << pa.shOrder << " twin " << pt.shOrder;

    BrdfTableOptions fixed = options(dir.path);
    fixed.orderOverride = 8;
    BrdfTableSet set;
    set.build({analytic, twin}, fixed);
    std::vector<double> fa, ft;
    double diff = 0.0, norm = 0.0;
    for (int t = 0; t < 16; ++t) {
      const double theta = 1.3 * t / 15.0;  // to 74°
      const Vec3 wo(float(std::sin(theta)), 0.0f, float(std::cos(theta)));
      set.lookup(set.plans()[0].tableIndex, wo, fa);
      set.lookup(set.plans()[1].tableIndex, wo, ft);
      for (size_t k = 0; k < fa.size(); ++k) {
        diff += (fa[k] - ft[k]) * (fa[k] - ft[k]);
        norm += fa[k] * fa[k];
      }
    }
    EXPECT_LT(std::sqrt(diff / norm), 0.01) << name;
  }
}

// A reflectance no analytic model has (a retro-reflective lobe): the bandwidth rule still gives it
// an order, with its truncation error within the tolerance.
TEST(MerlTables, NonAnalyticMaterialGetsAnOrderFromItsBandwidth) {
  ScratchDir dir;
  BrdfTableSet set;
  const BrdfTableOptions o = options(dir.path);
  set.build({test::merlTwin("retro")}, o);
  const MaterialPlan& p = set.plans()[0];
  EXPECT_EQ(p.technique, Technique::RadianceCache);
  EXPECT_GE(p.shOrder, 2);
  EXPECT_LE(p.shOrder, o.maxOrder);
  EXPECT_LE(p.truncationError, o.tolerance);
  EXPECT_GT(p.truncationError, 0.0);
}

// The disk cache key is the file's content: the same bytes under another name hit, changed bytes miss.
TEST(MerlTables, DiskCacheIsKeyedByTheFileContent) {
  ScratchDir dir;
  MerlData d = tabulateMerl(RetroReflectiveLobe(), 45, 45, 90);
  writeMerlFile(dir.path + "/a.binary", d);
  writeMerlFile(dir.path + "/b.binary", d);
  d.values[100] *= 1.5f;
  writeMerlFile(dir.path + "/c.binary", d);
  auto build = [&](const std::string& file) {
    BrdfTableSet set;
    set.build({test::make("merl", {test::str("filename", dir.path + "/" + file)})}, options(dir.path + "/cache"));
    return set.plans()[0].tableCacheHit;
  };
  EXPECT_FALSE(build("a.binary"));
  EXPECT_TRUE(build("b.binary"));
  EXPECT_FALSE(build("c.binary"));
  EXPECT_TRUE(build("a.binary"));
}

}  // namespace
}  // namespace rc
