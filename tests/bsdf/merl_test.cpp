// The merl BSDF: file validation, half/difference angles, evaluation against the analytic BSDF its
// table was made from, reciprocity, and its tabulated sampler (chi-square, weight = eval/pdf,
// albedo by sampling = albedo by quadrature).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "bsdf/merl_data.h"
#include "core/error.h"
#include "merl_twins.h"

namespace rc {
namespace {

using namespace rc::test;
namespace fs = std::filesystem;

std::string scratchPath(const std::string& name) {
  const fs::path dir = fs::current_path() / "merl_test_data";
  fs::create_directories(dir);
  return (dir / name).string();
}

// A small table (the format allows any axis lengths) with distinct values per entry.
MerlData smallTable() {
  MerlData d;
  d.thetaHalfRes = 6;
  d.thetaDiffRes = 5;
  d.phiDiffRes = 8;
  d.values.resize(3 * d.nodeCount());
  for (size_t s = 0; s < d.values.size(); ++s) d.values[s] = 0.01f * float(s % 97) + 0.001f;
  return d;
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

std::string readBytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

// The error message of readMerlFile, or "" when it succeeds.
std::string readError(const std::string& path, bool clamp = false) {
  try {
    readMerlFile(path, clamp);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(MerlFile, WriteThenReadKeepsValuesAndHashesTheContent) {
  const MerlData d = smallTable();
  const std::string path = scratchPath("roundtrip.binary");
  writeMerlFile(path, d);
  EXPECT_EQ(fs::file_size(path), 12u + 3 * d.nodeCount() * 8);
  const MerlData r = readMerlFile(path, false);
  ASSERT_EQ(r.thetaHalfRes, 6);
  ASSERT_EQ(r.thetaDiffRes, 5);
  ASSERT_EQ(r.phiDiffRes, 8);
  ASSERT_EQ(r.values.size(), d.values.size());
  for (size_t s = 0; s < d.values.size(); ++s) ASSERT_NEAR(r.values[s], d.values[s], 1e-6f * d.values[s]) << s;
  EXPECT_NE(r.contentHash, 0u);
  MerlData other = d;
  other.values[5] *= 2.0f;
  writeMerlFile(path, other);
  EXPECT_NE(readMerlFile(path, false).contentHash, r.contentHash);
}

TEST(MerlFile, MalformedFilesGiveOneMessageNamingTheFile) {
  const std::string path = scratchPath("bad.binary");
  writeMerlFile(path, smallTable());
  const std::string good = readBytes(path);

  EXPECT_NE(readError(scratchPath("missing.binary")).find("missing.binary: cannot open"), std::string::npos);
  EXPECT_NE(readError(fs::current_path().string()).find(": is a directory"), std::string::npos);

  writeBytes(path, good.substr(0, 7));
  EXPECT_NE(readError(path).find(path + ": truncated header"), std::string::npos) << readError(path);

  writeBytes(path, good.substr(0, good.size() - 8));
  const std::string shortMsg = readError(path);
  EXPECT_NE(shortMsg.find(path + ": header says 6x5x8"), std::string::npos) << shortMsg;
  EXPECT_NE(shortMsg.find("(truncated)"), std::string::npos) << shortMsg;

  writeBytes(path, good + "x");
  EXPECT_NE(readError(path).find("but the file has " + std::to_string(good.size() + 1) + " bytes"), std::string::npos);

  std::string dims = good;
  const int32_t huge = 1 << 20;
  std::memcpy(&dims[4], &huge, 4);  // a header that would ask for terabytes
  writeBytes(path, dims);
  EXPECT_NE(readError(path).find("header dimension 1 is 1048576"), std::string::npos) << readError(path);

  const size_t entry = 12 + 8 * (3 * 240 - 1);  // last entry: channel 2, last node
  std::string nan = good;
  const double nanValue = std::nan("");
  std::memcpy(&nan[entry], &nanValue, 8);
  writeBytes(path, nan);
  EXPECT_NE(readError(path).find("channel 2, theta_h 5, theta_d 4, phi_d 7) is not finite"), std::string::npos)
      << readError(path);

  std::string negative = good;
  const double minusOne = -1.0;
  std::memcpy(&negative[12], &minusOne, 8);
  writeBytes(path, negative);
  EXPECT_NE(readError(path).find("value 0 (channel 0, theta_h 0, theta_d 0, phi_d 0) is negative"), std::string::npos)
      << readError(path);
  EXPECT_EQ(readError(path, true), "");
  EXPECT_EQ(readMerlFile(path, true).values[0], 0.0f);
}

TEST(MerlFile, FactoryReadsTheFileAndRequiresAName) {
  const std::string path = scratchPath("factory.binary");
  writeMerlFile(path, smallTable());
  const BsdfPtr b = make("merl", {str("filename", path)});
  EXPECT_EQ(b->typeName(), "merl");
  EXPECT_NE(b->parameterKey().find("content="), std::string::npos);
  EXPECT_THROW(make("merl"), Error);
  EXPECT_THROW(make("merl", {str("filename", scratchPath("missing.binary"))}), Error);
}

TEST(MerlAngles, DirectionsFromHalfDiffInvertHalfDiffAngles) {
  Rng rng(5);
  for (int k = 0; k < 2000; ++k) {
    const double th = 0.5 * kPiD * rng.nextDouble(), td = 0.5 * kPiD * rng.nextDouble(), pd = kPiD * rng.nextDouble();
    Vec3 wi, wo;
    directionsFromHalfDiff(th, td, pd, &wi, &wo);
    const HalfDiffAngles a = halfDiffAngles(wi, wo);
    ASSERT_NEAR(a.thetaHalf, th, 2e-3);  // float directions: acos near 0 loses precision
    ASSERT_NEAR(a.thetaDiff, td, 2e-3);
    if (td > 0.01) {
      const double dp = std::fabs(a.phiDiff - pd);
      ASSERT_LT(std::min(dp, kPiD - dp), 2e-2) << th << " " << td << " " << pd;
    }
    const HalfDiffAngles swapped = halfDiffAngles(wo, wi);  // reciprocity: same angles after the fold
    ASSERT_NEAR(swapped.thetaDiff, a.thetaDiff, 1e-4);
    const double ds = std::fabs(swapped.phiDiff - a.phiDiff);
    if (td > 0.01) ASSERT_LT(std::min(ds, kPiD - ds), 2e-3);
  }
}

// The interpolated table against the BSDF it was made from, at random pairs with θ_i, θ_o ≤ 70°
// (toward the horizon the table's last θ_d row is 1° from it and the one-sided cut-off falls
// inside cells). The mean relative error, weighted by the value, is the table's discretisation
// error, 0.04–0.11% for these lobes with trilinear lookup; 0.5% leaves room for other seeds.
TEST(MerlBsdf, EvalMatchesTheAnalyticBsdfOfItsTable) {
  for (const char* name : {"ggx", "beckmann", "lambert", "mix"}) {
    const BsdfPtr analytic = analyticForTwin(name), twin = merlTwin(name);
    Rng rng(17);
    double err = 0.0, sum = 0.0;
    for (int k = 0; k < 20000; ++k) {
      const double co = std::cos(70.0 / 180.0 * kPiD);
      const Vec3 wo = dirFrom(co + (1 - co) * rng.nextDouble(), 2 * kPiD * rng.nextDouble());
      // Half of the pairs near the mirror direction, where the highlights are.
      Vec3 wi = dirFrom(co + (1 - co) * rng.nextDouble(), 2 * kPiD * rng.nextDouble());
      if (k % 2) {
        wi = glm::normalize(Vec3(-wo.x, -wo.y, wo.z) + 0.3f * Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 0.0f));
        if (wi.z < co) continue;
      }
      const Color a = analytic->eval(wo, wi), t = twin->eval(wo, wi);
      for (int c = 0; c < 3; ++c) {
        err += std::fabs(double(t[c]) - a[c]);
        sum += a[c];
      }
    }
    EXPECT_LT(err / sum, 0.005) << name;
  }
}

TEST(MerlBsdf, ReciprocalAndOneSided) {
  for (const char* name : {"mix", "retro"}) {
    const BsdfPtr b = merlTwin(name);
    Rng rng(3);
    for (int k = 0; k < 2000; ++k) {
      Vec3 wo = uniformSphere(rng), wi = uniformSphere(rng);
      EXPECT_EQ(b->eval(Vec3(wo.x, wo.y, -std::fabs(wo.z)), wi), Color(0.0f));
      EXPECT_EQ(b->pdf(wo, Vec3(wi.x, wi.y, -std::fabs(wi.z))), 0.0f);
      wo.z = std::fabs(wo.z);
      wi.z = std::fabs(wi.z);
      if (wo.z < 1e-2f || wi.z < 1e-2f) continue;
      const Color fa = b->eval(wo, wi) / wi.z, fb = b->eval(wi, wo) / wo.z;
      // Float half/difference angles differ by ~1e-6 rad between the two orders.
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(fa[c], fb[c], 1e-3f * fa[c] + 1e-6f) << name;
    }
  }
}

struct MerlSamplingCase {
  const char* twin;
  float cosThetaO, phiO;
};
const MerlSamplingCase kSamplingCases[] = {
    {"ggx", 1.0f, 0.0f},    {"ggx", 0.6f, 0.4f},    {"ggx", 0.05f, 2.0f},  {"mix", 0.8f, 1.0f},
    {"mix", 0.2f, 4.0f},    {"lambert", 0.5f, 0.0f}, {"retro", 0.9f, 0.3f}, {"retro", 0.4f, 5.5f},
    {"retro", 0.08f, 1.0f}, {"beckmann", 0.3f, 3.0f},
};
constexpr int kNumSamplingCases = sizeof(kSamplingCases) / sizeof(kSamplingCases[0]);

class MerlSampling : public ::testing::TestWithParam<int> {};

TEST_P(MerlSampling, ChiSquare) {
  const MerlSamplingCase& c = kSamplingCases[GetParam()];
  const BsdfPtr b = merlTwin(c.twin);
  const Chi2Result r = chi2ForBsdf(*b, dirFrom(c.cosThetaO, c.phiO), 500 + GetParam());
  const double alpha = 1.0 - std::pow(1.0 - 1e-3, 1.0 / kNumSamplingCases);  // Šidák, as BsdfSampling
  EXPECT_FALSE(r.observedWhereImpossible);
  EXPECT_GT(r.pValue, alpha) << c.twin << " chi2 = " << r.statistic << ", dof = " << r.dof;
}

// The sampler follows the data: the estimator of the albedo ∫ f cos dω from 4096 samples has a
// small spread, and equals the albedo by quadrature (a wrong pdf would bias it).
TEST_P(MerlSampling, WeightIsEvalOverPdfAndTheAlbedoIsUnbiased) {
  const MerlSamplingCase& c = kSamplingCases[GetParam()];
  const BsdfPtr b = merlTwin(c.twin);
  const Vec3 wo = dirFrom(c.cosThetaO, c.phiO);
  Rng rng(91 + GetParam(), 5);
  double sum = 0.0, sum2 = 0.0;
  const int n = 4096;
  for (int k = 0; k < n; ++k) {
    const auto s = b->sample(wo, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
    if (!s) continue;
    const float pdf = b->pdf(wo, s->wi);
    const Color f = b->eval(wo, s->wi);
    ASSERT_NEAR(s->pdf, pdf, 1e-4f * pdf);
    for (int ch = 0; ch < 3; ++ch) ASSERT_NEAR(s->weight[ch], f[ch] / pdf, 1e-4f * f[ch] / pdf + 1e-7f);
    const double w = (double(s->weight.r) + s->weight.g + s->weight.b) / 3.0;
    sum += w;
    sum2 += w * w;
  }
  const double mean = sum / n, var = sum2 / n - mean * mean, stderr_ = std::sqrt(var / n);
  const double quadrature = integrateSphere([&](const Vec3& wi) {
    const Color f = b->eval(wo, wi);
    return (double(f.r) + f.g + f.b) / 3.0;
  }, 64, 64);
  EXPECT_NEAR(mean, quadrature, 5.0 * stderr_ + 2e-3 * quadrature) << c.twin;
  // Importance sampling worth the name: the weight's relative spread is 0.07–0.3 for these cases;
  // 0.5 fails a sampler that misses the lobe.
  EXPECT_LT(std::sqrt(var) / mean, 0.5) << c.twin;
}

INSTANTIATE_TEST_SUITE_P(Twins, MerlSampling, ::testing::Range(0, kNumSamplingCases),
                         [](const ::testing::TestParamInfo<int>& info) {
                           const MerlSamplingCase& c = kSamplingCases[info.param];
                           return std::string(c.twin) + "_" + std::to_string(info.param);
                         });

// Furnace: the Lambert twin reflects its albedo, the twins' albedos equal the analytic ones within
// 0.5% (the table's discretisation moves them by up to 0.16%).
TEST(MerlBsdf, AlbedoEqualsTheAnalyticBsdfs) {
  for (const char* name : {"ggx", "beckmann", "lambert", "mix"}) {
    const BsdfPtr analytic = analyticForTwin(name), twin = merlTwin(name);
    for (float co : {1.0f, 0.7f, 0.4f}) {
      const Vec3 wo = dirFrom(co, 0.3);
      auto albedo = [&](const Bsdf& b) {
        return integrateSphere([&](const Vec3& wi) { return double(b.eval(wo, wi).g); }, 128, 64);
      };
      const double a = albedo(*analytic), t = albedo(*twin);
      EXPECT_NEAR(t, a, 0.005 * a) << name << " cos " << co;
    }
  }
  const double lambert = integrateSphere([&](const Vec3& wi) { return double(merlTwin("lambert")->eval(Vec3(0, 0, 1), wi).b); });
  EXPECT_NEAR(lambert, 0.8, 0.008);
}

}  // namespace
}  // namespace rc
