// <medium>, <phase>, <volume> and the volume texture as the loader reads them (scene/medium.h,
// texture/volume.h): values from Mitsuba's definitions, and one precise file:line error per
// hostile input.
#include <array>
#include <cstring>

#include "scene_test_util.h"
#include "texture/volume.h"

namespace rc::test {
namespace {

// A `.vol` file (scene/volume_grid_file.h) of x·y·z voxels with `channels` float32 values each.
std::string volFile(int x, int y, int z, int channels, const std::vector<float>& values,
                    const std::array<float, 6>& bounds = {0, 0, 0, 0, 0, 0}) {
  std::string s = "VOL\x03";
  auto i32 = [&](int32_t v) {
    for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>((static_cast<uint32_t>(v) >> (8 * i)) & 0xff));
  };
  auto f32 = [&](float f) {
    int32_t b;
    std::memcpy(&b, &f, 4);
    i32(b);
  };
  i32(1);
  i32(x), i32(y), i32(z), i32(channels);
  for (const float b : bounds) f32(b);
  for (float v : values) f32(v);
  return s;
}

const std::string kBox = R"(<shape type="cube">%MEDIA%<bsdf type="null"/></shape>)";

std::string withMedia(const std::string& media) {
  std::string s = kBox;
  return s.replace(s.find("%MEDIA%"), 7, media);
}

TEST(MediumLoad, HomogeneousMediumOnShapesAndSensor) {
  TempDir dir;
  // Defined before the sensor that refers to it (rcache resolves references in document order).
  const std::string xml = sceneXml(R"(
  <sensor type="perspective"><ref id="fog"/></sensor>)" + withMedia(R"(<ref id="fog" name="interior"/><medium type="homogeneous" name="exterior"/>)"),
                                   R"(
  <medium type="homogeneous" id="fog">
    <float name="sigma_t" value="2"/>
    <float name="scale" value="1.5"/>
    <rgb name="albedo" value="0.2, 0.4, 0.6"/>
    <phase type="hg"><float name="g" value="-0.3"/></phase>
    <boolean name="sample_emitters" value="false"/>
    <boolean name="has_spectral_extinction" value="false"/>
  </medium>)");
  const Scene s = loadScene(dir.write("s.xml", xml));
  ASSERT_EQ(s.media.size(), 2u);
  const Medium& fog = s.media[0];
  EXPECT_EQ(fog.sigmaT, Color(3.0f));
  EXPECT_EQ(fog.albedo->eval(Vec3(5.0f)), Color(0.2f, 0.4f, 0.6f));
  EXPECT_EQ(fog.phase.type, PhaseFunction::Type::HenyeyGreenstein);
  EXPECT_FLOAT_EQ(fog.phase.g, -0.3f);
  EXPECT_FALSE(fog.sampleEmitters);
  // Mitsuba's defaults: sigma_t 1, albedo 0.75, isotropic, emitter sampling on.
  const Medium& plain = s.media[1];
  EXPECT_EQ(plain.sigmaT, Color(1.0f));
  EXPECT_EQ(plain.albedo->eval(Vec3(0.0f)), Color(0.75f));
  EXPECT_EQ(plain.phase.type, PhaseFunction::Type::Isotropic);
  EXPECT_TRUE(plain.sampleEmitters);
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].media.interior, 0);
  EXPECT_EQ(s.meshes[0].media.exterior, 1);
  EXPECT_EQ(s.cameraMedium, 0);
}

// Trilinear lookups between voxel centres at (i + ½)/n of the unit cube, with Dr.Jit's wraps, and
// to_world placing the cube: values hand-computed from v(x, y, z) = x + 2y + 4z on a 2×2×2 grid.
TEST(MediumLoad, GridVolumeTrilinearNearestAndWrapModes) {
  TempDir dir;
  std::vector<float> v;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) v.push_back(float(x + 2 * y + 4 * z));
  dir.write("g.vol", volFile(2, 2, 2, 1, v));
  auto albedoOf = [&](const std::string& params) {
    const std::string xml = sceneXml(R"(<medium type="homogeneous" id="m"><volume type="gridvolume" name="albedo">
        <string name="filename" value="g.vol"/>)" + params + R"(</volume></medium>)");
    // Albedo in [0, 1] is checked at load: scale the grid's 0..7 down through the test's lookup.
    return loadScene(dir.write("v.xml", xml)).media.at(0).albedo;
  };
  // Values 0..7 are no albedo: the loader refuses them, naming the parameter's line.
  expectError([&] { albedoOf(""); }, {"v.xml:", "'albedo' must lie in [0, 1]"});
  // The same grid scaled into [0, 1] (×1/7): every expected value below is divided by 7 too.
  for (float& x : v) x /= 7.0f;
  dir.write("g.vol", volFile(2, 2, 2, 1, v));
  const VolumePtr clamp = albedoOf("");
  EXPECT_NEAR(clamp->eval({0.5f, 0.5f, 0.5f}).r, 3.5f / 7, 1e-6f);           // the middle: mean of all
  EXPECT_NEAR(clamp->eval({0.25f, 0.75f, 0.25f}).g, 2.0f / 7, 1e-6f);        // a voxel centre
  EXPECT_NEAR(clamp->eval({0.5f, 0.25f, 0.25f}).b, 0.5f / 7, 1e-6f);
  EXPECT_NEAR(clamp->eval({0.1f, 0.25f, 0.25f}).r, 0.0f, 1e-6f);             // clamped below the first centre
  const VolumePtr repeat = albedoOf(R"(<string name="wrap_mode" value="repeat"/>)");
  // x = 0.1·2 − ½ = −0.3: between voxel −1 (= 1 when repeating) and 0, weight 0.3 on the first.
  EXPECT_NEAR(repeat->eval({0.1f, 0.25f, 0.25f}).r, 0.3f / 7, 1e-6f);
  EXPECT_NEAR(repeat->eval({1.1f, 0.25f, 0.25f}).r, 0.3f / 7, 1e-6f);
  // Far points (beyond int range in voxels) stay inside the grid's values, without overflow.
  for (const VolumePtr& vol : {clamp, repeat}) {
    const float far = vol->eval({1e30f, -1e30f, 5e9f}).r;
    EXPECT_GE(far, 0.0f);
    EXPECT_LE(far, 1.0f);
  }
  const VolumePtr mirror = albedoOf(R"(<string name="wrap_mode" value="mirror"/>)");
  EXPECT_NEAR(mirror->eval({0.1f, 0.25f, 0.25f}).r, 0.0f, 1e-6f);            // voxel −1 mirrors to 0
  EXPECT_NEAR(mirror->eval({1.1f, 0.25f, 0.25f}).r, 1.0f / 7, 1e-6f);        // voxels 2, 1 mirror to 1, 1
  const VolumePtr nearest = albedoOf(R"(<string name="filter_type" value="nearest"/>)");
  EXPECT_NEAR(nearest->eval({0.49f, 0.51f, 0.9f}).r, 6.0f / 7, 1e-6f);
  const VolumePtr placed = albedoOf(R"(<transform name="to_world"><scale value="2"/><translate x="1"/></transform>)");
  EXPECT_NEAR(placed->eval({2.0f, 1.0f, 1.0f}).r, 3.5f / 7, 1e-6f);          // world (2,1,1) = local (½,½,½)
  EXPECT_NEAR(placed->maximum().r, 1.0f, 1e-6f);
}

// Mitsuba's heterogeneous medium: extinction scale · sigma_t(p) within the sigma_t volume's bounds
// (a gridvolume's to_world; a float is a constvolume over the unit cube), majorant scale · the
// grid's largest value of any channel.
TEST(MediumLoad, HeterogeneousMediumTakesItsBoundsAndMajorantFromSigmaT) {
  TempDir dir;
  dir.write("d.vol", volFile(2, 1, 1, 1, {0.5f, 2.0f}));
  dir.write("b.vol", volFile(2, 1, 1, 1, {0.5f, 2.0f}, {-1, 0, 0, 3, 2, 0.5f}));
  const Scene s = loadScene(dir.write("s.xml", sceneXml(R"(
  <medium type="heterogeneous" id="smoke">
    <volume type="gridvolume" name="sigma_t">
      <string name="filename" value="d.vol"/>
      <transform name="to_world"><scale x="4" y="2" z="2"/><translate x="-2" y="-1" z="-1"/></transform>
    </volume>
    <float name="scale" value="3"/>
    <float name="albedo" value="0.9"/>
    <phase type="hg"><float name="g" value="0.4"/></phase>
  </medium>
  <medium type="heterogeneous" id="plain"><float name="sigma_t" value="0.5"/></medium>
  <medium type="heterogeneous" id="boxed">
    <volume type="gridvolume" name="sigma_t">
      <string name="filename" value="b.vol"/>
      <boolean name="use_grid_bbox" value="true"/>
      <float name="max_value" value="5"/>
      <transform name="to_world"><translate x="10"/></transform>
    </volume>
  </medium>)")));
  ASSERT_EQ(s.media.size(), 3u);
  const Medium& smoke = s.media[0];
  EXPECT_FALSE(smoke.homogeneous);
  EXPECT_FLOAT_EQ(smoke.majorant, 6.0f);
  EXPECT_EQ(smoke.density->bounds().lo, Vec3(-2, -1, -1));
  EXPECT_EQ(smoke.density->bounds().hi, Vec3(2, 1, 1));
  EXPECT_NEAR(smoke.extinctionAt(Vec3(0.0f)).r, 3.0f * 1.25f, 1e-5f);  // between the voxel centres
  EXPECT_EQ(smoke.albedo->eval(Vec3(0.0f)), Color(0.9f));
  EXPECT_EQ(smoke.phase.type, PhaseFunction::Type::HenyeyGreenstein);
  const Medium& plain = s.media[1];
  EXPECT_FLOAT_EQ(plain.majorant, 0.5f);
  EXPECT_EQ(plain.density->bounds().lo, Vec3(0.0f));
  EXPECT_EQ(plain.density->bounds().hi, Vec3(1.0f));
  EXPECT_EQ(plain.albedo->eval(Vec3(0.0f)), Color(0.75f));
  // use_grid_bbox: the file's bounds (−1,0,0)…(3,2,0.5) are the cube, then to_world; max_value is
  // the majorant.
  const Medium& boxed = s.media[2];
  EXPECT_EQ(boxed.density->bounds().lo, Vec3(9, 0, 0));
  EXPECT_EQ(boxed.density->bounds().hi, Vec3(13, 2, 0.5f));
  EXPECT_NEAR(boxed.extinctionAt(Vec3(11, 1, 0.25f)).r, 1.25f, 1e-5f);
  EXPECT_FLOAT_EQ(boxed.majorant, 5.0f);
}

// Hostile heterogeneous media: negative or non-finite densities, a majorant that overflows, and one
// so large that a ray across the volume would take more than kMaxCollisionsAcross lookups.
TEST(MediumLoad, HostileHeterogeneousMediaAreOnePreciseError) {
  TempDir dir;
  auto load = [&](const std::string& body) { return loadScene(dir.write("h.xml", sceneXml(body))); };
  auto medium = [](const std::string& params) { return "<medium type=\"heterogeneous\" id=\"m\">\n" + params + "\n</medium>"; };
  auto grid = [](const std::string& file) {
    return R"(<volume type="gridvolume" name="sigma_t"><string name="filename" value=")" + file + R"("/></volume>)";
  };
  dir.write("neg.vol", volFile(2, 1, 1, 1, {1.0f, -0.5f}));
  dir.write("nan.vol", volFile(2, 1, 1, 1, {1.0f, std::nanf("")}));
  dir.write("big.vol", volFile(2, 1, 1, 1, {1.0f, 3e38f}));
  dir.write("ok.vol", volFile(2, 1, 1, 1, {1.0f, 2.0f}));
  // A nested volume's problems are the medium's (line 3); a property's are its own line.
  expectError([&] { load(medium(grid("neg.vol"))); }, {"h.xml:3", "'sigma_t' must be non-negative"});
  expectError([&] { load(medium(grid("nan.vol"))); }, {"nan.vol"});
  expectError([&] { load(medium(grid("big.vol") + R"(<float name="scale" value="10"/>)")); }, {"h.xml:3", "majorant", "not finite"});
  expectError([&] { load(medium(grid("ok.vol") + R"(<float name="scale" value="1e6"/>)")); },
              {"h.xml:3", "expected null collisions per ray", "lower 'scale'"});
  expectError([&] { load(medium(R"(<float name="scale" value="nan"/>)")); }, {"h.xml:4", "scale", "not a finite number"});
  expectError([&] { load(medium(R"(<volume type="gridvolume" name="sigma_t"><string name="filename" value="ok.vol"/>
    <float name="max_value" value="1.5"/></volume>)")); }, {"h.xml:5", "'max_value' must be finite and at least the grid's largest value 2"});
  expectError([&] { load(medium(R"(<volume type="gridvolume" name="sigma_t"><string name="filename" value="ok.vol"/>
    <boolean name="use_grid_bbox" value="true"/></volume>)")); }, {"h.xml:4", "singular"});  // the file's bounds are all 0
  // Empty (zero majorant) is a vacuum, not an error.
  EXPECT_EQ(load(medium(R"(<float name="sigma_t" value="0"/>)")).media.at(0).majorant, 0.0f);
}

// Mitsuba's `volume` texture: the volume at the shading point's world position; a 3-channel grid
// keeps its channels.
TEST(MediumLoad, VolumeTextureReadsTheWorldPosition) {
  TempDir dir;
  dir.write("c.vol", volFile(1, 1, 2, 3, {0.1f, 0.2f, 0.3f, 0.7f, 0.8f, 0.9f}));
  const Scene s = loadScene(dir.write("t.xml", sceneXml(R"(
  <texture type="volume" id="t"><volume type="gridvolume" name="volume">
    <string name="filename" value="c.vol"/><string name="filter_type" value="nearest"/>
  </volume></texture>
  <bsdf type="diffuse" id="d"><ref name="reflectance" id="t"/></bsdf>
  <shape type="sphere"><ref id="d"/></shape>)")));
  ASSERT_EQ(s.bsdfs.size(), 1u);
  const Bsdf& bsdf = *s.bsdfs[0];
  ASSERT_TRUE(bsdf.tinted());
  TexturePoint low, high;
  low.position = Vec3(0.5f, 0.5f, 0.2f);
  high.position = Vec3(0.5f, 0.5f, 0.8f);
  const Vec3 wo(0, 0, 1);
  EXPECT_NEAR(bsdf.tint(low, wo).g, 0.2f, 1e-6f);
  EXPECT_NEAR(bsdf.tint(high, wo).b, 0.9f, 1e-6f);
}

TEST(MediumLoad, HostileMediaAreOnePreciseError) {
  TempDir dir;
  auto load = [&](const std::string& body) { return loadScene(dir.write("h.xml", sceneXml(body))); };
  auto medium = [](const std::string& params) { return "<medium type=\"homogeneous\" id=\"m\">\n" + params + "\n</medium>"; };
  expectError([&] { load(medium(R"(<float name="sigma_t" value="-1"/>)")); }, {"h.xml:4", "'sigma_t' must be non-negative"});
  expectError([&] { load(medium(R"(<rgb name="albedo" value="0.5, 1.2, 0.5"/>)")); }, {"h.xml:4", "'albedo' must lie in [0, 1]"});
  expectError([&] { load(medium(R"(<float name="albedo" value="-0.1"/>)")); }, {"h.xml:4", "'albedo' must lie in [0, 1]"});
  expectError([&] { load(medium(R"(<float name="scale" value="-2"/>)")); }, {"h.xml:4", "'scale' must be non-negative"});
  expectError([&] { load(medium(R"(<phase type="hg"><float name="g" value="1"/></phase>)")); },
              {"h.xml:4", "'g' must lie in (-1, 1)"});
  expectError([&] { load(medium(R"(<phase type="hg"><float name="g" value="-1.5"/></phase>)")); }, {"h.xml:4", "(-1, 1)"});
  expectError([&] { load(medium(R"(<phase type="rayleigh"/>)")); }, {"h.xml:4", "unknown phase function 'rayleigh'"});
  expectError([&] { load(medium(R"(<phase type="hg"/><phase type="isotropic"/>)")); }, {"h.xml:4", "one phase function"});
  expectError([&] { load(medium(R"(<float name="density" value="1"/>)")); }, {"h.xml:4", "unsupported parameter 'density'"});
  expectError([&] { load(R"(<medium type="inhomogeneous"/>)"); }, {"h.xml:3", "unknown medium plugin 'inhomogeneous'", "heterogeneous"});
  expectError([&] { load(withMedia(R"(<ref id="nowhere" name="interior"/>)")); }, {"h.xml:3", "unknown id 'nowhere'"});
  expectError([&] { load(R"(<bsdf type="diffuse" id="b"/>)" + withMedia(R"(<ref id="b" name="exterior"/>)")); },
              {"h.xml:3", "id 'b'", "is not a medium"});
  expectError([&] { load(withMedia(R"(<medium type="homogeneous"/>)")); }, {"h.xml:3", "name=\"interior\""});
  expectError([&] { load(withMedia(R"(<medium type="homogeneous" name="interior"/><medium type="homogeneous" name="interior"/>)")); },
              {"h.xml:3", "interior medium is given twice"});
  expectError([&] { load(medium(R"(<volume type="gridvolume" name="albedo"><string name="filename" value="none.vol"/></volume>)")); },
              {"h.xml:4", "none.vol"});
  expectError([&] { load(R"(<texture type="volume" id="t"/>)"); }, {"h.xml:3", "<volume name=\"volume\">"});
}

}  // namespace
}  // namespace rc::test
