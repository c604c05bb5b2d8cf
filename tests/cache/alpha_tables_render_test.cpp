// Textured roughness through the radiance cache (brdf/material_plan.h, tables over α): the nodes and
// the per-point choice between them, and a roughconductor floor with a checkerboard roughness on the
// box scene — cached, not importance-sampled — agreeing with the path tracer per 16-px block.
#include <gtest/gtest.h>

#include <cmath>

#include "block_agreement.h"
#include "material_stats.h"
#include "brdf/material_plan.h"
#include "test_scene.h"
#include "texture/texture.h"

namespace rc::test {
namespace {

TEST(AlphaTables, NodesAreGeometricAndCoverTheRange) {
  const std::vector<float> nodes = alphaNodesOver(0.1f, 0.8f);
  ASSERT_GE(nodes.size(), 2u);
  EXPECT_LE(nodes.size(), size_t(kMaxAlphaNodes));
  EXPECT_FLOAT_EQ(nodes.front(), 0.1f);
  EXPECT_FLOAT_EQ(nodes.back(), 0.8f);
  for (size_t k = 1; k < nodes.size(); ++k) {
    EXPECT_LE(nodes[k] / nodes[k - 1], std::sqrt(2.0f) * 1.0001f);
    EXPECT_NEAR(nodes[k] / nodes[k - 1], nodes[1] / nodes[0], 1e-4f);
  }
  EXPECT_EQ(alphaNodesOver(0.3f, 0.3f).size(), 1u);
  EXPECT_EQ(alphaNodesOver(1e-3f, 1.0f).size(), size_t(kMaxAlphaNodes));  // ratio capped by the count
}

// The upper node is chosen with probability t = log(α/α_k)/log(α_k+1/α_k); outside: the end nodes.
TEST(AlphaTables, PointChoiceInterpolatesInLogAlpha) {
  MaterialPlan plan;
  plan.tableIndex = 7;
  EXPECT_EQ(plan.tableAt(0.3f, 0.5f), 7);
  plan.alphaNodes = {0.1f, 0.2f, 0.4f};
  plan.alphaTables = {3, 4, 5};
  EXPECT_EQ(plan.tableAt(0.05f, 0.99f), 3);
  EXPECT_EQ(plan.tableAt(0.9f, 0.0f), 5);
  const float alpha = 0.1f * std::pow(2.0f, 0.25f);  // a quarter of the way from 0.1 to 0.2 in log α
  int upper = 0;
  const int n = 10000;
  for (int i = 0; i < n; ++i) upper += plan.tableAt(alpha, (i + 0.5f) / n) == 4;
  EXPECT_NEAR(upper, 0.25 * n, 2);
  EXPECT_EQ(plan.tableAt(0.3f, 0.99f), 4);  // between 0.2 and 0.4, t ≈ 0.58
  EXPECT_EQ(plan.tableAt(0.3f, 0.01f), 5);
}

// The box scene's floor (test::glossy's roughconductor) with its α a 4×4 checkerboard of 0.3 and 0.6;
// the parameter itself holds the mean, as the loader sets it.
Scene roughTexturedBox(int size) {
  Scene s = boxScene(0.0f, size, size);
  Properties props;
  props.pluginType = "roughconductor";
  props.set("distribution", stringProp("ggx"));
  props.set("alpha", floatProp(0.45));
  props.set("material", stringProp("none"));
  props.set("specular_reflectance", rgbProp(0.8f, 0.8f, 0.8f));
  UvTransform toUv;
  toUv.m = Mat3(4.0f);
  toUv.m[2][2] = 1.0f;
  s.bsdfs[0] = createBsdf(props, {}, "floor", {{"alpha", makeCheckerboard(Color(0.3f), Color(0.6f), toUv)}});
  s.meshes[0].uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  return s;
}

// rcache may be 3 % off per block for the cache's interpolation bias (as on the normal-mapped floor,
// tests/cache/normal_map_render_test.cpp).
TEST(AlphaTables, RoughnessTexturedFloorThroughTheCacheAgreesPerBlock) {
  constexpr int kSize = 48, kSeeds = 4, kSpp = 16, kRefSpp = 256;
  const Scene s = roughTexturedBox(kSize);
  const Image ref = renderScene(s, pathSettings(s), kRefSpp, 999).image;
  std::vector<Image> cached;
  RenderStats stats;
  for (int k = 1; k <= kSeeds; ++k) {
    RenderResult r = renderScene(s, rcacheSettings(s, {{"fallback", "false"}}), kSpp, 300 + k);
    cached.push_back(std::move(r.image));
    stats = std::move(r.stats);
  }
  expectBlocksAgree(cached, kSpp, ref, kRefSpp, kSize, kSize, 0.03, "rcache");
  // The check can tell: the floor at the texture's mean α (one table for the whole floor) fails it.
  Scene uniform = s;
  uniform.bsdfs[0] = glossy(0.45f);
  std::vector<Image> meanAlpha;
  for (int k = 1; k <= kSeeds; ++k)
    meanAlpha.push_back(renderScene(uniform, rcacheSettings(uniform, {{"fallback", "false"}}), kSpp, 300 + k).image);
  EXPECT_GT(blockExcess(meanAlpha, kSpp, ref, kRefSpp, kSize, kSize, 0.03, "mean alpha", false), 0.0);
  const std::string entry = materialEntry(stats, "floor");
  EXPECT_NE(entry.find("radiance cache"), std::string::npos) << entry;
  const size_t nodes = entry.find("\"alpha_nodes\": ");
  ASSERT_NE(nodes, std::string::npos) << entry;
  EXPECT_GE(std::stoi(entry.substr(nodes + 15)), 2) << entry;  // α 0.3 … 0.6: several nodes
}

}  // namespace
}  // namespace rc::test
