// EnvmapLight::lookupAdd (the envmap's pass over a wave of directions, vectorised) against the
// scalar lookup() it must reproduce bit for bit, on every instruction-set version this CPU runs.
#include <gtest/gtest.h>

#include <iostream>

#include "common/float_bits.h"
#include "core/rng.h"
#include "render/envmap_light.h"

namespace rc {
namespace {

using test::bits;

// A map with a smooth gradient, a bright texel and a dark column at the seam, rotated so that the
// map's frame is not the world's.
EnvmapLight testMap() {
  const int W = 37, H = 19;  // odd sizes: no power-of-two index arithmetic to hide a wrong stride
  std::vector<Color> px;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      px.push_back(x == 0 ? Color(0.01f) : (x == 23 && y == 6) ? Color(50.0f, 30.0f, 20.0f)
                                                               : Color(0.2f + 0.03f * x, 0.4f + 0.05f * y, 1.0f / (1 + x + y)));
  const Vec3 up = glm::normalize(Vec3(0.3f, 1.0f, -0.2f)), side = glm::normalize(glm::cross(up, Vec3(1, 0, 0)));
  const Mat3 toWorld(glm::cross(up, side), up, side);  // a rotation: orthonormal columns, det +1
  return EnvmapLight(W, H, px, 1.5f, toWorld);
}

// Directions over the whole sphere, and the ones where the mapping has its special cases: the axes
// (poles, the seam at u = 0, signed zeros), just off them, and lengths other than 1.
std::vector<Vec3> testDirections() {
  std::vector<Vec3> d;
  for (float s : {1.0f, -1.0f}) {
    d.push_back(Vec3(s, 0, 0)), d.push_back(Vec3(0, s, 0)), d.push_back(Vec3(0, 0, s));
    d.push_back(Vec3(s * 1e-7f, 1, 0)), d.push_back(Vec3(0, s, -1e-7f)), d.push_back(Vec3(-0.0f, 0, s));
    d.push_back(Vec3(1e-30f, -0.0f, s)), d.push_back(Vec3(s * 3.0f, 2.0f, -5.0f));
  }
  Rng rng(17);
  while (d.size() < 4099) {  // not a multiple of any vector width: the loops' tails run too
    const float z = 1 - 2 * rng.nextFloat(), phi = 2 * kPi * rng.nextFloat(), r = std::sqrt(std::max(0.0f, 1 - z * z));
    d.push_back(Vec3(r * std::cos(phi), r * std::sin(phi), z) * (0.5f + rng.nextFloat()));
  }
  return d;
}

TEST(EnvmapLightBatch, EveryVersionIsTheScalarLookupBitForBit) {
  const EnvmapLight env = testMap();
  const std::vector<Vec3> dirs = testDirections();
  const size_t n = dirs.size();
  std::vector<float> x(n), y(n), z(n);
  for (size_t k = 0; k < n; ++k) x[k] = dirs[k].x, y[k] = dirs[k].y, z[k] = dirs[k].z;
  const float selectProb = 0.3f;
  const int levels = static_cast<int>(cpuSimdLevel());
  for (int l = 0; l <= levels; ++l) {
    const SimdLevel level = static_cast<SimdLevel>(l);
    std::cout << "[ version  ] " << simdLevelName(level) << "\n";
    for (bool withPdf : {true, false}) {
      // Running sums that already hold something: lookupAdd adds to them.
      std::vector<float> r(n, 0.25f), g(n, 0.5f), b(n, 0.0f), pdf(n, 0.125f);
      env.lookupAdd(x.data(), y.data(), z.data(), n, selectProb, r.data(), g.data(), b.data(),
                    withPdf ? pdf.data() : nullptr, level);
      size_t lit = 0;
      for (size_t k = 0; k < n; ++k) {
        const EnvmapLight::Lookup one = env.lookup(dirs[k]);
        ASSERT_EQ(bits(r[k]), bits(0.25f + one.radiance.r)) << simdLevelName(level) << " direction " << k;
        ASSERT_EQ(bits(g[k]), bits(0.5f + one.radiance.g)) << simdLevelName(level) << " direction " << k;
        ASSERT_EQ(bits(b[k]), bits(0.0f + one.radiance.b)) << simdLevelName(level) << " direction " << k;
        const float expectedPdf = withPdf ? 0.125f + selectProb * one.pdf : 0.125f;
        ASSERT_EQ(bits(pdf[k]), bits(expectedPdf)) << simdLevelName(level) << " direction " << k;
        lit += one.pdf > 0.0f;
      }
      EXPECT_GT(lit, n - 16);  // the densities compared are real ones (0 only at the poles)
    }
  }
}

}  // namespace
}  // namespace rc
