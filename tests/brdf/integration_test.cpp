// The tables as the renderer uses them: through rc::ref::brdfDot (the brdf_dot contract shared
// with the kernels) and with the project's real BSDFs from the factory (host/bsdf).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "brdf/material_plan.h"
#include "brdf/table_layout.h"
#include "brute_force.h"
#include "bsdf/bsdf_factory.h"
#include "common/property_builders.h"
#include "core/rng.h"
#include "sh/reference.h"
#include "sh/sh_basis.h"
#include "test_bsdfs.h"

namespace rc {
namespace {

using test::floatProp;
using test::stringProp;

BsdfPtr roughConductor(const std::string& distribution, double alpha) {
  Properties props;
  props.pluginType = "roughconductor";
  props.set("distribution", stringProp(distribution));
  props.set("alpha", floatProp(alpha));
  return createBsdf(props, {}, "rc_" + distribution + "_" + std::to_string(alpha));
}

BsdfPtr roughPlastic(double alpha) {
  Properties props;
  props.pluginType = "roughplastic";
  props.set("distribution", stringProp("ggx"));
  props.set("alpha", floatProp(alpha));
  return createBsdf(props, {}, "plastic");
}

BsdfPtr diffuse() {
  Properties props;
  props.pluginType = "diffuse";
  return createBsdf(props, {}, "white");
}

std::string tempDir() {
  char tmpl[] = "/tmp/rc_brdf_int_XXXXXX";
  return mkdtemp(tmpl);
}

BrdfTableOptions testOptions(const std::string& dir) {
  BrdfTableOptions o;
  o.cacheDir = dir;
  o.isotropicRes = 32;
  o.anisotropicRes = 9;
  o.orderOverride = 4;  // L below is order 4: the dot product is then exact up to quadrature/interpolation
  o.notice = [](const std::string&) {};
  return o;
}

// Our CPU lookup and the reference brdf_dot (different code, same contract) agree to float
// rounding for 1-D (rotated) and 2-D tables, including ω_o below the horizon (→ 0).
TEST(BrdfIntegration, LookupAgreesWithReferenceBrdfDot) {
  const std::string dir = tempDir();
  std::vector<BsdfPtr> scene{test::ggx(0.4f), std::make_shared<test::TestMicrofacet>(true, 0.3f, 0.6f)};
  BrdfTableSet set;
  BrdfTableOptions opt = testOptions(dir);
  opt.orderOverride = 5;
  set.build(scene, opt);
  ASSERT_EQ(set.tables().size(), 2u);
  BrdfDotBatch batch;
  batch.order = 6;  // higher than the tables': missing coefficients are zero
  const int n2 = 36;
  set.fillBatch(batch);
  Rng rng(99);
  batch.points = 400;
  for (int p = 0; p < batch.points; ++p) {
    for (int k = 0; k < 3 * n2; ++k) batch.lambda.push_back(float(2 * rng.nextDouble() - 1));
    const double z = p % 50 == 0 ? -0.2 : rng.nextDouble(), phi = 2 * kPiD * rng.nextDouble();
    const double s = std::sqrt(1 - z * z);
    batch.wo.insert(batch.wo.end(), {float(s * std::cos(phi)), float(s * std::sin(phi)), float(z)});
    batch.material.push_back(p % 2);
  }
  std::vector<float> out;
  ref::brdfDot(batch, out);
  std::vector<double> F;
  for (int p = 0; p < batch.points; ++p) {
    const Vec3 wo(batch.wo[3 * p], batch.wo[3 * p + 1], batch.wo[3 * p + 2]);
    set.lookup(batch.material[p], wo, F);
    const int tn2 = 25;
    for (int c = 0; c < 3; ++c) {
      double dot = 0, mag = 0;
      for (int i = 0; i < tn2; ++i) {
        dot += F[c * tn2 + i] * batch.lambda[(p * 3 + c) * n2 + i];
        mag += std::fabs(F[c * tn2 + i] * batch.lambda[(p * 3 + c) * n2 + i]);
      }
      // float32 table and lambda, 25-term sums: ~1e-6 relative to Σ|terms|.
      EXPECT_NEAR(out[p * 3 + c], dot, 1e-5 * mag + 1e-7) << "point " << p;
    }
  }
  std::filesystem::remove_all(dir);
}

struct RadianceAcc {
  const std::vector<double>* L = nullptr;
  double sum[3] = {0, 0, 0}, albedo[3] = {0, 0, 0};
  void add(const glm::dvec3& w, const double gdw[3]) {
    double y[16];
    sh::evalBasis(4, w.x, w.y, w.z, y);
    for (int ch = 0; ch < 3; ++ch) {
      double l = 0;
      for (int i = 0; i < 16; ++i) l += (*L)[ch * 16 + i] * y[i];
      sum[ch] += l * gdw[ch];
      albedo[ch] += gdw[ch];
    }
  }
  void merge(const RadianceAcc& o) {
    for (int ch = 0; ch < 3; ++ch) sum[ch] += o.sum[ch], albedo[ch] += o.albedo[ch];
  }
};

// The project's BSDFs (GGX and Beckmann rough conductors, rough plastic with its diffuse base,
// Lambertian): Λ·F(ω_o) through rc::ref::brdfDot equals the brute-force ∫ L·f_r·cos for an
// order-4 L, between table nodes and up to 85°. Tolerance 2% of albedo·⟨L⟩ as in
// DotProductMatchesDirectIntegral (quadrature ≲ 0.5%, interpolation in x with T = 32 ≲ 1%).
TEST(BrdfIntegration, RealBsdfsDotProductMatchesDirectIntegral) {
  const std::string dir = tempDir();
  std::vector<BsdfPtr> scene{roughConductor("ggx", 0.1), roughConductor("beckmann", 0.3), roughPlastic(0.2), diffuse()};
  BrdfTableSet set;
  set.build(scene, testOptions(dir));
  EXPECT_EQ(set.plans()[3].technique, Technique::IrradianceCache);
  Rng rng(5);
  std::vector<double> L(48);
  for (int i = 0; i < 48; ++i) L[i] = i % 16 == 0 ? std::sqrt(4 * kPiD) : 0.3 * (2 * rng.nextDouble() - 1);
  BrdfDotBatch batch;
  batch.order = 4;
  set.fillBatch(batch);
  std::vector<Vec3> dirs;
  for (double th : {5.0, 37.0, 63.0, 85.0}) {
    const double t = th * kPiD / 180, p = 0.3 + th / 30;
    dirs.push_back(Vec3(float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t))));
  }
  for (size_t m = 0; m < scene.size(); ++m)
    for (const Vec3& wo : dirs) {
      batch.lambda.insert(batch.lambda.end(), L.begin(), L.end());
      batch.wo.insert(batch.wo.end(), {wo.x, wo.y, wo.z});
      batch.material.push_back(set.plans()[m].tableIndex);
      ++batch.points;
    }
  std::vector<float> out;
  ref::brdfDot(batch, out);
  for (int p = 0; p < batch.points; ++p) {
    const size_t m = p / dirs.size();
    const Vec3 wo = dirs[p % dirs.size()];
    RadianceAcc zero;
    zero.L = &L;
    const RadianceAcc direct = test::bruteForce(*scene[m], wo, 500, 1000, zero);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(out[p * 3 + c], direct.sum[c], 0.02 * direct.albedo[c] + 1e-6)
          << scene[m]->id << " theta " << std::acos(wo.z) * 180 / kPiD << " ch " << c;
  }
  std::filesystem::remove_all(dir);
}

// Automatic order choice on the real BSDFs: sharp conductors are importance-sampled, rough ones
// cached, and the order never falls as the lobe sharpens.
TEST(BrdfIntegration, RealBsdfOrdersMonotone) {
  const std::string dir = tempDir();
  for (const std::string dist : {"ggx", "beckmann"}) {
    std::vector<BsdfPtr> scene;
    for (double a : {1.0, 0.5, 0.3, 0.2, 0.1, 0.05}) scene.push_back(roughConductor(dist, a));
    BrdfTableSet set;
    BrdfTableOptions o;
    o.cacheDir = dir;
    o.isotropicRes = 4;  // the tables are not checked here
    o.tableQuadrature = LobeQuadrature{64, 64};
    o.notice = [](const std::string&) {};
    set.build(scene, o);
    int previous = 0;
    for (const MaterialPlan& p : set.plans()) {
      const int order = p.technique == Technique::ImportanceSampling ? 17 : p.shOrder;
      EXPECT_GE(order, previous) << dist << " " << p.name;
      previous = order;
    }
    EXPECT_EQ(set.plans().front().technique, Technique::RadianceCache) << dist;
    EXPECT_EQ(set.plans().back().technique, Technique::ImportanceSampling) << dist;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rc
