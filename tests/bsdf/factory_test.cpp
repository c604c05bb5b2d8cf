// Factory table: known types, nesting rules, parameter validation messages and parameter keys.
#include <gtest/gtest.h>

#include "bsdf/bsdf_factory.h"
#include "common/property_builders.h"
#include "core/error.h"

namespace rc {
namespace {

using test::floatProp;
using test::stringProp;

Properties props(const std::string& type) {
  Properties p;
  p.pluginType = type;
  return p;
}

// Expects createBsdf to throw rc::Error whose message mentions `needle`.
void expectError(const Properties& p, const std::vector<BsdfPtr>& nested, const std::string& needle) {
  try {
    createBsdf(p, nested);
    FAIL() << "no error for " << p.pluginType << ", expected '" << needle << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(BsdfFactory, KnownTypes) {
  for (const char* t : {"diffuse", "roughconductor", "conductor", "plastic", "roughplastic", "dielectric", "thindielectric", "twosided",
                        "blendbsdf", "roughdielectric", "null", "mask", "principled", "pplastic", "polarizer"})
    EXPECT_TRUE(isKnownBsdfType(t)) << t;
  EXPECT_FALSE(isKnownBsdfType("principledthin"));
  expectError(props("nosuch"), {}, "unknown BSDF plugin 'nosuch'");
}

TEST(BsdfFactory, DefaultsAndIds) {
  BsdfPtr d = createBsdf(props("diffuse"), {});
  EXPECT_EQ(d->typeName(), "diffuse");
  EXPECT_EQ(d->id.rfind("diffuse#", 0), 0u);
  EXPECT_TRUE(d->isDiffuseOnly());
  EXPECT_EQ(createBsdf(props("diffuse"), {}, "wall")->id, "wall");
  BsdfPtr r = createBsdf(props("roughconductor"), {});
  EXPECT_FLOAT_EQ(r->glossyAlpha(), 0.1f);  // Mitsuba default alpha
  EXPECT_NE(r->parameterKey().find("beckmann"), std::string::npos);  // Mitsuba default distribution
}

TEST(BsdfFactory, RejectsBadParameters) {
  Properties p = props("roughconductor");
  p.set("alpha", floatProp(0.0));
  expectError(p, {}, "'alpha'");
  p = props("roughconductor");
  p.set("alpha", floatProp(NAN));
  expectError(p, {}, "'alpha'");
  p = props("roughconductor");
  p.set("alpha_u", floatProp(0.1));
  expectError(p, {}, "alpha_v");
  p = props("diffuse");
  p.set("reflectance", floatProp(-0.1));
  expectError(p, {}, "'reflectance'");
  p = props("conductor");
  p.set("eta", floatProp(NAN));
  expectError(p, {}, "'eta'");
  p = props("conductor");
  p.set("material", stringProp("Unobtainium"));
  expectError(p, {}, "unknown conductor material 'Unobtainium'");
  p = props("conductor");
  p.set("material", stringProp("Au"));
  p.set("eta", floatProp(1.5));
  expectError(p, {}, "not both");
  p = props("roughconductor");
  p.set("k", floatProp(-1));
  expectError(p, {}, "'k'");
  p = props("roughconductor");
  p.set("distribution", stringProp("phong"));
  expectError(p, {}, "'distribution'");
  BsdfPtr d = createBsdf(props("diffuse"), {});
  p = props("blendbsdf");
  p.set("weight", floatProp(1.5));
  expectError(p, {d, d}, "'weight'");
  expectError(props("blendbsdf"), {d}, "nested");
  expectError(props("twosided"), {}, "nested");
  expectError(props("diffuse"), {d}, "nested");
}

// Named conductors reflect at normal incidence what their RGB η, k give: ((η−1)² + k²)/((η+1)² + k²),
// with Mitsuba 3.9.1's RGB values for gold (η = 0.143036, 0.375307, 1.44205; k = 3.983, 2.38556, 1.60336).
TEST(BsdfFactory, ConductorMaterialPresets) {
  Properties p = props("conductor");
  p.set("material", stringProp("Au"));
  const BsdfPtr gold = createBsdf(p, {});
  const auto s = gold->sample(Vec3(0, 0, 1), 0.5f, Vec2(0.5f));
  ASSERT_TRUE(s);
  const float eta[3] = {0.143036f, 0.375307f, 1.44205f}, k[3] = {3.983f, 2.38556f, 1.60336f};
  for (int c = 0; c < 3; ++c) {
    const float expected = ((eta[c] - 1) * (eta[c] - 1) + k[c] * k[c]) / ((eta[c] + 1) * (eta[c] + 1) + k[c] * k[c]);
    EXPECT_NEAR(s->weight[c], expected, 1e-4f) << c;
  }
  for (const char* name : {"Ag", "Al", "Cu", "Cr", "Cu_palik", "W"}) {
    Properties q = props("roughconductor");
    q.set("material", stringProp(name));
    EXPECT_NO_THROW(createBsdf(q, {})) << name;
  }
}

TEST(BsdfFactory, ParameterKeyDistinguishesValues) {
  Properties a = props("roughconductor"), b = props("roughconductor");
  a.set("alpha", floatProp(0.3));
  b.set("alpha", floatProp(std::nextafter(0.3f, 1.0f)));
  EXPECT_NE(createBsdf(a, {})->parameterKey(), createBsdf(b, {})->parameterKey());
  Properties a2 = props("roughconductor");
  a2.set("alpha", floatProp(0.3));
  EXPECT_EQ(createBsdf(a, {})->parameterKey(), createBsdf(a2, {})->parameterKey());
  BsdfPtr d1 = createBsdf(props("diffuse"), {});
  Properties g = props("diffuse");
  g.set("reflectance", floatProp(0.25));
  BsdfPtr d2 = createBsdf(g, {});
  // Nested keys are part of the wrapper's key.
  EXPECT_NE(createBsdf(props("twosided"), {d1})->parameterKey(), createBsdf(props("twosided"), {d2})->parameterKey());
  Properties unread = props("diffuse");
  unread.set("bogus", floatProp(1.0));
  createBsdf(unread, {});
  ASSERT_EQ(unread.unusedNames().size(), 1u);  // the parser reports it
}

TEST(BsdfFactory, NamedIorsAsMitsuba) {
  // "bk7" (1.5046) in "water" (1.333) equals the numeric ratio; names are case-insensitive.
  Properties named = props("dielectric"), numeric = props("dielectric");
  named.set("int_ior", stringProp("BK7"));
  named.set("ext_ior", stringProp("water"));
  numeric.set("int_ior", floatProp(1.5046));
  numeric.set("ext_ior", floatProp(1.333));
  EXPECT_EQ(createBsdf(named, {})->parameterKey(), createBsdf(numeric, {})->parameterKey());
  // Defaults: dielectric bk7/air, plastic polypropylene (1.49)/air.
  Properties dflt = props("dielectric"), explicitIor = props("dielectric");
  explicitIor.set("int_ior", stringProp("bk7"));
  explicitIor.set("ext_ior", stringProp("air"));
  EXPECT_EQ(createBsdf(dflt, {})->parameterKey(), createBsdf(explicitIor, {})->parameterKey());
  Properties plasticDefault = props("plastic"), acrylic = props("plastic");
  acrylic.set("int_ior", stringProp("acrylic glass"));  // 1.49 too
  EXPECT_EQ(createBsdf(plasticDefault, {})->parameterKey(), createBsdf(acrylic, {})->parameterKey());
  Properties bad = props("plastic");
  bad.set("int_ior", stringProp("unobtainium"));
  expectError(bad, {}, "unknown index-of-refraction name 'unobtainium'");
  bad = props("dielectric");
  bad.set("ext_ior", floatProp(-1.0));
  expectError(bad, {}, "'ext_ior'");
}

TEST(BsdfFactory, LobesAlphaAndIsotropy) {
  EXPECT_EQ(createBsdf(props("plastic"), {})->lobes(), uint32_t(kLobeDiffuse | kLobeDelta));
  EXPECT_EQ(createBsdf(props("dielectric"), {})->lobes(), uint32_t(kLobeDelta | kLobeTransmission));
  EXPECT_TRUE(std::isinf(createBsdf(props("conductor"), {})->glossyAlpha()));
  Properties aniso = props("roughconductor");
  aniso.set("alpha_u", floatProp(0.3));
  aniso.set("alpha_v", floatProp(0.2));
  BsdfPtr a = createBsdf(aniso, {});
  EXPECT_FALSE(a->isotropic());
  EXPECT_FLOAT_EQ(a->glossyAlpha(), 0.2f);
  BsdfPtr d = createBsdf(props("diffuse"), {});
  Properties blend = props("blendbsdf");
  blend.set("weight", floatProp(0.0));  // second BSDF has no weight: its lobe is absent
  BsdfPtr b = createBsdf(blend, {d, a});
  EXPECT_TRUE(b->isDiffuseOnly());
  EXPECT_FALSE(createBsdf(props("twosided"), {d, a})->isotropic());
  // roughplastic is isotropic only, like Mitsuba: alpha_u stays unread and the parser reports it.
  Properties rp = props("roughplastic");
  rp.set("alpha_u", floatProp(0.3));
  createBsdf(rp, {});
  EXPECT_EQ(rp.unusedNames(), std::vector<std::string>{"alpha_u"});
}

}  // namespace
}  // namespace rc
