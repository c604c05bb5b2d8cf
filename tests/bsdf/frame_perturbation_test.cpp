// normalmap and bumpmap (Mitsuba 3 semantics): the perturbed frame, the point BSDF's factors in the
// unperturbed frame (same-side cut, Estevez et al.'s shadowing term), the flip of invalid normals,
// the bumpmap normal from the height field's gradient, and the bitmap's gradient itself. Expected
// values come from the plugins' definitions, computed here independently.
#include <gtest/gtest.h>

#include <cmath>

#include "bsdf/plugins.h"
#include "bsdf_test_util.h"
#include "core/error.h"
#include "texture/texture.h"

namespace rc {
namespace {

using test::boolean;
using test::make;
using test::rgb;

constexpr float kRho = 0.5f;

// normalmap around a diffuse BSDF, with a constant normal n = (sin θ, 0, cos θ) (tilted toward t).
BsdfPtr tiltedNormalMap(float tiltRad, bool shadowing, bool flip = true) {
  const float s = std::sin(tiltRad), c = std::cos(tiltRad);
  return make("normalmap",
              {rgb("normalmap", 0.5f * (s + 1.0f), 0.5f, 0.5f * (c + 1.0f)), boolean("use_shadowing_function", shadowing),
               boolean("flip_invalid_normals", flip)},
              {make("diffuse", {rgb("reflectance", kRho, kRho, kRho)})});
}

FramePoint pointSeenFrom(const Vec3& wo) {
  FramePoint p;
  p.uv = Vec2(0.3f, 0.6f);
  p.wo = glm::normalize(wo);
  return p;
}

// The value the point BSDF gives for light from `l` (unperturbed local coordinates), in its frame.
Color evalToward(const Bsdf& material, const FramePoint& p, const Vec3& l) {
  const Frame f = material.perturbedFrame(p);
  const BsdfPtr point = material.atFrame(p.uv, f.toLocal(Vec3(0, 0, 1)));
  return point->eval(f.toLocal(p.wo), f.toLocal(glm::normalize(l)));
}

float tan2(float c) { return (1.0f - c * c) / (c * c); }

TEST(NormalMap, ConstantTiltGivesTheCosineToTheTiltedNormal) {
  const float tilt = 30.0f * kPi / 180.0f;
  const Vec3 n(std::sin(tilt), 0.0f, std::cos(tilt));
  const BsdfPtr m = tiltedNormalMap(tilt, false);
  ASSERT_TRUE(m->perturbsFrame());
  const FramePoint p = pointSeenFrom(Vec3(0.1f, 0.2f, 1.0f));
  const Frame f = m->perturbedFrame(p);
  EXPECT_NEAR(glm::dot(f.n, n), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(f.t, f.n), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(glm::cross(f.t, f.b), f.n), 1.0f, 1e-6f);  // right-handed
  for (const Vec3 l : {Vec3(0.4f, 0.1f, 0.9f), Vec3(-0.3f, 0.5f, 0.8f), Vec3(0.9f, -0.2f, 0.3f)}) {
    const float cosN = glm::dot(n, glm::normalize(l));
    EXPECT_NEAR(evalToward(*m, p, l).g, kRho / kPi * cosN, 1e-6f) << l.x << "," << l.y << "," << l.z;
  }
}

TEST(NormalMap, ShadowingTermOfEstevez2019) {
  const float tilt = 35.0f * kPi / 180.0f;
  const Vec3 n(std::sin(tilt), 0.0f, std::cos(tilt));
  const BsdfPtr m = tiltedNormalMap(tilt, true);
  const FramePoint p = pointSeenFrom(Vec3(0.0f, 0.0f, 1.0f));
  for (const Vec3 l : {Vec3(0.4f, 0.1f, 0.9f), Vec3(0.9f, -0.2f, 0.2f), Vec3(0.0f, 0.3f, 1.0f)}) {
    const Vec3 ln = glm::normalize(l);
    const float alpha2 = std::fmin(0.125f * tan2(n.z), 1.0f);
    const float g = 2.0f / (1.0f + std::sqrt(1.0f + alpha2 * tan2(ln.z)));
    EXPECT_LT(g, 1.0f);
    EXPECT_NEAR(evalToward(*m, p, l).g, kRho / kPi * glm::dot(n, ln) * g, 1e-6f);
  }
}

// Light below the unperturbed tangent plane but above the perturbed one is cut (Mitsuba's
// cos θ·cos θ' > 0 test), and so is what sample() would return there.
TEST(NormalMap, LightBelowTheUnperturbedPlaneIsCut) {
  const float tilt = 40.0f * kPi / 180.0f;
  const BsdfPtr m = tiltedNormalMap(tilt, false);
  const FramePoint p = pointSeenFrom(Vec3(0.0f, 0.0f, 1.0f));
  const Vec3 l(1.0f, 0.0f, -0.2f);  // above the tilted plane: n·l > 0
  ASSERT_GT(glm::dot(Vec3(std::sin(tilt), 0.0f, std::cos(tilt)), glm::normalize(l)), 0.1f);
  EXPECT_EQ(evalToward(*m, p, l), Color(0.0f));
  const Frame f = m->perturbedFrame(p);
  const BsdfPtr point = m->atFrame(p.uv, f.toLocal(Vec3(0, 0, 1)));
  const Vec3 wo = f.toLocal(p.wo);
  Rng rng(7);
  int cut = 0;
  for (int i = 0; i < 4000; ++i) {
    const auto s = point->sample(wo, rng.nextFloat(), rng.next2D());
    if (!s) {
      ++cut;
      continue;
    }
    EXPECT_GT(f.toWorld(s->wi).z, 0.0f);  // f's world is the unperturbed local frame
    EXPECT_NEAR(point->pdf(wo, s->wi), s->pdf, 1e-4f * s->pdf);
  }
  // A cosine lobe about n projects uniformly onto n's unit disk, where the plane z = 0 is a half
  // ellipse of semi-axes 1 and cos θ: the share below it is (1 − cos θ)/2. Within 5σ (binomial).
  const double share = 0.5 * (1.0 - std::cos(tilt)), sigma = std::sqrt(4000.0 * share * (1.0 - share));
  EXPECT_NEAR(cut, 4000.0 * share, 5.0 * sigma);
}

// Seen from a side where the perturbed normal faces away from the viewer, the normal is mirrored
// about the unperturbed one (flip_invalid_normals), unless disabled.
TEST(NormalMap, InvalidNormalsFlipTowardTheViewer) {
  const float tilt = 50.0f * kPi / 180.0f;
  const FramePoint p = pointSeenFrom(Vec3(-1.0f, 0.0f, 0.3f));
  ASSERT_LT(glm::dot(p.wo, Vec3(std::sin(tilt), 0.0f, std::cos(tilt))), 0.0f);
  const Frame flipped = tiltedNormalMap(tilt, false, true)->perturbedFrame(p);
  EXPECT_NEAR(flipped.n.x, -std::sin(tilt), 1e-6f);
  EXPECT_NEAR(flipped.n.z, std::cos(tilt), 1e-6f);
  const Frame kept = tiltedNormalMap(tilt, false, false)->perturbedFrame(p);
  EXPECT_NEAR(kept.n.x, std::sin(tilt), 1e-6f);
}

// The scene-level BSDF is the nested one (its coefficient tables), and normalmap may not be nested.
TEST(NormalMap, TablesAreTheNestedBsdfsAndNestingIsRefused) {
  const BsdfPtr diffuse = make("diffuse", {rgb("reflectance", kRho, kRho, kRho)});
  const BsdfPtr m = tiltedNormalMap(0.3f, true);
  EXPECT_EQ(m->parameterKey(), diffuse->parameterKey());
  EXPECT_EQ(m->lobes(), diffuse->lobes());
  EXPECT_EQ(m->typeName(), "normalmap");
  EXPECT_FALSE(m->isTwoSided());
  EXPECT_TRUE(make("normalmap", {rgb("normalmap", 0.5f, 0.5f, 1.0f)}, {make("twosided", {}, {diffuse})})->isTwoSided());
  try {
    make("twosided", {}, {m});
    ADD_FAILURE() << "nested normalmap accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("outermost"), std::string::npos) << e.what();
  }
  EXPECT_THROW(make("normalmap", {}, {diffuse}), Error);  // no normal map
}

// A 4×1 grey ramp 0, ¼, ½, ¾ (bilinear, clamp): inside, ∂h/∂u = ¼ per texel = 1 per unit u.
TexturePtr ramp(const UvTransform& toUv = {}) {
  std::vector<Color> px;
  for (int i = 0; i < 4; ++i) px.push_back(Color(0.25f * i));
  return makeBitmapTexture(4, 1, px, TextureFilter::Bilinear, TextureWrap::Clamp, toUv);
}

TEST(BitmapGradient, BilinearDerivativeAndItsUvTransform) {
  const TexturePtr t = ramp();
  ASSERT_TRUE(t->hasGradient());
  const Vec2 g = t->gradient1(Vec2(0.5f, 0.5f));
  EXPECT_NEAR(g.x, 1.0f, 1e-5f);
  EXPECT_NEAR(g.y, 0.0f, 1e-6f);
  // Against a central difference of the texture's own luminance.
  const float h = 1e-3f;
  const float fd = (luminance(t->eval(TexturePoint(Vec2(0.4f + h, 0.5f)))) - luminance(t->eval(TexturePoint(Vec2(0.4f - h, 0.5f))))) / (2 * h);
  EXPECT_NEAR(t->gradient1(Vec2(0.4f, 0.5f)).x, fd, 1e-2f);
  // to_uv scaling u by ½ halves the derivative along u.
  UvTransform half;
  half.m[0][0] = 0.5f;
  EXPECT_NEAR(ramp(half)->gradient1(Vec2(1.0f, 0.5f)).x, 0.5f, 1e-5f);
  EXPECT_EQ(makeBitmapTexture(4, 1, std::vector<Color>(4, Color(0.2f)), TextureFilter::Nearest, TextureWrap::Clamp, {})
                ->gradient1(Vec2(0.5f)),
            Vec2(0.0f));
  EXPECT_FALSE(makeCheckerboard(Color(0.1f), Color(0.9f), {})->hasGradient());
}

BsdfPtr bumpmap(TexturePtr height, float scale) {
  Properties props;
  props.pluginType = "bumpmap";
  Property s;
  s.type = Property::Type::Float;
  s.number = scale;
  props.set("scale", s);
  Property mean;
  mean.type = Property::Type::Float;
  mean.number = 0.5;
  props.set(kBumpMapTextureParameter, mean);
  Property noShadow;
  noShadow.type = Property::Type::Boolean;
  noShadow.boolean = false;
  props.set("use_shadowing_function", noShadow);
  return createBsdf(props, {test::make("diffuse", {rgb("reflectance", kRho, kRho, kRho)})}, "bump",
                    {{kBumpMapTextureParameter, std::move(height)}});
}

// dp/du = (2, 0, 0), dp/dv = (0, 2, 0): with ∂h/∂u = s, dp/du' = (2, 0, s), dp/dv' = (0, 2, 0), so
// n ∝ dp/du' × dp/dv' = (−2s, 0, 4).
TEST(BumpMap, NormalFromTheScaledHeightGradient) {
  for (const float scale : {0.5f, 2.0f, -1.0f}) {
    const BsdfPtr b = bumpmap(ramp(), scale);
    FramePoint p = pointSeenFrom(Vec3(0, 0, 1));
    p.uv = Vec2(0.5f, 0.5f);
    p.dpdu = Vec3(2, 0, 0);
    p.dpdv = Vec3(0, 2, 0);
    p.ng = Vec3(0, 0, 1);
    const Frame f = b->perturbedFrame(p);
    const Vec3 expected = glm::normalize(Vec3(-2.0f * scale, 0.0f, 4.0f));
    EXPECT_NEAR(glm::dot(f.n, expected), 1.0f, 1e-6f) << scale;
    EXPECT_NEAR(glm::dot(f.t, glm::normalize(Vec3(2, 0, 0) - f.n * glm::dot(f.n, Vec3(2, 0, 0)))), 1.0f, 1e-6f);
    const Vec3 l = glm::normalize(Vec3(0.3f, -0.4f, 0.8f));
    EXPECT_NEAR(evalToward(*b, p, l).g, kRho / kPi * glm::dot(expected, l), 1e-6f);
    // Without partials (a mesh without uvs) the frame stays.
    p.dpdu = p.dpdv = Vec3(0.0f);
    EXPECT_NEAR(b->perturbedFrame(p).n.z, 1.0f, 1e-6f);
  }
  EXPECT_THROW(bumpmap(makeCheckerboard(Color(0.1f), Color(0.9f), {}), 1.0f), Error);
}

}  // namespace
}  // namespace rc
