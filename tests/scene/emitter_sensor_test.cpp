// Emitters, sensor, film, rfilter, sampler and integrator: values, defaults and error paths.
#include <OpenImageIO/imageio.h>

#include "scene_test_util.h"

namespace rc::test {
namespace {

TEST(SceneEmitters, AreaEmitterAttachesToItsShape) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("<shape type=\"cube\"/>"
                                         "<shape type=\"rectangle\"><emitter type=\"area\"><rgb name=\"radiance\" value=\"10, 9, 8\"/></emitter></shape>"
                                         "<shape type=\"sphere\"><emitter type=\"area\"/></shape>"));
  ASSERT_EQ(s.emitters.size(), 2u);
  EXPECT_EQ(s.emitters[0].type, EmitterType::Area);
  EXPECT_EQ(s.emitters[0].radiance, Color(10, 9, 8));
  EXPECT_EQ(s.emitters[0].mesh, 1);
  EXPECT_EQ(s.meshes[1].emitter, 0);
  EXPECT_EQ(s.meshes[0].emitter, -1);
  EXPECT_EQ(s.emitters[1].sphere, 0);
  EXPECT_EQ(s.spheres[0].emitter, 1);
  EXPECT_EQ(s.emitters[1].radiance, Color(1.0f));
}

TEST(SceneEmitters, PointAndDirectional) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml(
      "<emitter type=\"point\"><point name=\"position\" value=\"1, 2, 3\"/><rgb name=\"intensity\" value=\"5\"/></emitter>"
      "<emitter type=\"point\"><transform name=\"to_world\"><translate x=\"4\"/></transform></emitter>"
      "<emitter type=\"directional\"><vector name=\"direction\" value=\"0, -2, 0\"/><rgb name=\"irradiance\" value=\"3\"/></emitter>"
      "<emitter type=\"directional\"><transform name=\"to_world\"><rotate x=\"1\" angle=\"90\"/></transform></emitter>"));
  ASSERT_EQ(s.emitters.size(), 4u);
  EXPECT_EQ(s.emitters[0].position, Vec3(1, 2, 3));
  EXPECT_EQ(s.emitters[0].intensity, Color(5));
  EXPECT_EQ(s.emitters[1].position, Vec3(4, 0, 0));
  EXPECT_EQ(s.emitters[2].direction, Vec3(0, -1, 0));
  EXPECT_EQ(s.emitters[2].irradiance, Color(3));
  // +90° about x takes local +z to −y.
  EXPECT_NEAR(s.emitters[3].direction.y, -1.0f, 1e-6f);
}

TEST(SceneEmitters, ConstantAndOnlyOneEnvironment) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("<emitter type=\"constant\"><rgb name=\"radiance\" value=\"0.5\"/></emitter>"));
  ASSERT_EQ(s.emitters.size(), 1u);
  EXPECT_EQ(s.emitters[0].type, EmitterType::Constant);
  EXPECT_EQ(s.emitters[0].radiance, Color(0.5f));
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"constant\"/>\n<emitter type=\"constant\"/>")); },
              {"scene.xml:4:", "only one environment emitter"});
}

TEST(SceneEmitters, EnvmapIsReadWithOpenImageIO) {
  TempDir dir;
  const int w = 4, h = 2;
  std::vector<float> px(w * h * 3);
  for (size_t i = 0; i < px.size(); ++i) px[i] = float(i);
  {
    auto out = OIIO::ImageOutput::create(dir.path("env.exr"));
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(dir.path("env.exr"), OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    out->close();
  }
  const Scene s = loadText(dir, sceneXml("<emitter type=\"envmap\"><string name=\"filename\" value=\"env.exr\"/>"
                                         "<float name=\"scale\" value=\"2\"/><transform name=\"to_world\"><rotate y=\"1\" angle=\"90\"/></transform></emitter>"));
  ASSERT_EQ(s.emitters.size(), 1u);
  const Emitter& e = s.emitters[0];
  EXPECT_EQ(e.type, EmitterType::Envmap);
  EXPECT_EQ(e.envWidth, w);
  EXPECT_EQ(e.envHeight, h);
  ASSERT_EQ(e.envPixels.size(), size_t(w * h));
  EXPECT_EQ(e.envPixels[5], Color(15, 16, 17));  // row 1, column 1: top row first
  EXPECT_EQ(e.scale, 2.0f);
  EXPECT_NEAR(e.toWorld[2][0], 1.0f, 1e-6f);  // local +z → world +x
}

TEST(SceneEmitters, EnvmapErrors) {
  TempDir dir;
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"envmap\"><string name=\"filename\" value=\"none.exr\"/></emitter>")); },
              {"scene.xml:3:", "<emitter type=\"envmap\">", "none.exr", "not found"});
  dir.write("junk.exr", "this is not an image");
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"envmap\"><string name=\"filename\" value=\"junk.exr\"/></emitter>")); },
              {"<emitter type=\"envmap\">", "junk.exr"});
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"envmap\"/>")); }, {"missing parameter 'filename'"});
}

TEST(SceneEmitters, Errors) {
  TempDir dir;
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"area\"/>")); }, {"must be nested inside a <shape>"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"cube\"><emitter type=\"point\"/></shape>")); }, {"only an area emitter"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"cube\"><emitter type=\"area\"/><emitter type=\"area\"/></shape>")); },
              {"one emitter"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"cube\"><emitter type=\"area\">\n<rgb name=\"radiance\" value=\"-1\"/></emitter></shape>")); },
              {"scene.xml:4:", "non-negative"});
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"directional\"><vector name=\"direction\" value=\"0 0 0\"/></emitter>")); },
              {"direction is zero"});
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"point\"><point name=\"position\" value=\"0 0 0\"/>"
                                           "<transform name=\"to_world\"/></emitter>")); }, {"not both"});
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"point\"><float name=\"radiance\" value=\"1\"/></emitter>")); },
              {"unsupported parameter 'radiance'"});
}

TEST(SceneSensor, PerspectiveFilmSampler) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("", R"(<sensor type="perspective">
      <float name="fov" value="45"/><string name="fov_axis" value="smaller"/>
      <float name="near_clip" value="0.1"/><float name="far_clip" value="100"/>
      <transform name="to_world"><translate z="-3"/></transform>
      <film type="hdrfilm"><integer name="width" value="320"/><integer name="height" value="200"/>
        <string name="pixel_format" value="rgb"/><string name="component_format" value="float32"/>
        <rfilter type="gaussian"><float name="stddev" value="0.3"/></rfilter></film>
      <sampler type="independent"><integer name="sample_count" value="64"/><integer name="seed" value="7"/></sampler>
    </sensor>)"));
  EXPECT_EQ(s.camera.fovDegrees, 45.0f);
  EXPECT_EQ(s.camera.fovAxis, "smaller");
  EXPECT_NEAR(s.camera.nearClip, 0.1f, 1e-7f);
  EXPECT_EQ(s.camera.farClip, 100.0f);
  EXPECT_EQ(Vec3(s.camera.toWorld[3]), Vec3(0, 0, -3));
  EXPECT_EQ(s.film.width, 320);
  EXPECT_EQ(s.film.height, 200);
  EXPECT_EQ(s.film.filter, "gaussian");
  EXPECT_NEAR(s.film.gaussianStddev, 0.3f, 1e-7f);
  EXPECT_EQ(s.sampler.sampleCount, 64);
  EXPECT_EQ(s.sampler.seed, 7u);
  EXPECT_EQ(s.sampler.type, "independent");
  const Scene b = loadText(dir, sceneXml("", "<sensor type=\"perspective\"><film type=\"hdrfilm\"><rfilter type=\"box\"/></film></sensor>"));
  EXPECT_EQ(b.film.filter, "box");
  EXPECT_EQ(b.sampler.type, "independent");  // Mitsuba's default
}

// ldsampler, and Mitsuba's stratified family served by it (their parameters are read, not
// reported as unused).
TEST(SceneSensor, LowDiscrepancySamplers) {
  TempDir dir;
  auto sampler = [&](const std::string& body) {
    return loadText(dir, sceneXml("", "<sensor type=\"perspective\">" + body + "</sensor>"));
  };
  const Scene ld = sampler("<sampler type=\"ldsampler\"><integer name=\"sample_count\" value=\"32\"/></sampler>");
  EXPECT_EQ(ld.sampler.type, "ldsampler");
  EXPECT_EQ(ld.sampler.sampleCount, 32);
  EXPECT_EQ(sampler("<sampler type=\"stratified\"><boolean name=\"jitter\" value=\"true\"/></sampler>").sampler.type, "ldsampler");
  EXPECT_EQ(sampler("<sampler type=\"multijitter\"/>").sampler.type, "ldsampler");
  EXPECT_EQ(sampler("<sampler type=\"orthogonal\"><float name=\"strength\" value=\"2\"/></sampler>").sampler.type, "ldsampler");
}

TEST(SceneSensor, BadValuesAreErrors) {
  TempDir dir;
  auto bad = [&](const std::string& sensorBody, std::initializer_list<std::string> parts) {
    expectError([&] { loadText(dir, sceneXml("", "<sensor type=\"perspective\">\n" + sensorBody + "</sensor>")); }, parts);
  };
  bad("<float name=\"fov\" value=\"180\"/>", {"scene.xml:3:", "<sensor type=\"perspective\">", "'fov' must be in (0, 180)"});
  bad("<float name=\"fov\" value=\"0\"/>", {"'fov'"});
  bad("<float name=\"fov\" value=\"30\"/><string name=\"fov_axis\" value=\"z\"/>", {"fov_axis"});
  bad("<float name=\"near_clip\" value=\"0\"/>", {"near_clip"});
  bad("<float name=\"near_clip\" value=\"10\"/><float name=\"far_clip\" value=\"1\"/>", {"far_clip"});
  bad("<transform name=\"to_world\"><scale value=\"2\"/></transform>", {"must not scale"});
  bad("<film type=\"hdrfilm\"><integer name=\"width\" value=\"0\"/></film>", {"scene.xml:3:", "<film type=\"hdrfilm\">", "'width' must be in 1..16384"});
  bad("<film type=\"hdrfilm\"><integer name=\"height\" value=\"-5\"/></film>", {"'height'"});
  bad("<film type=\"hdrfilm\"><integer name=\"width\" value=\"20000\"/></film>", {"'width'"});
  bad("<film type=\"hdrfilm\"><integer name=\"width\" value=\"16384\"/><integer name=\"height\" value=\"16384\"/></film>", {"2^26"});
  bad("<film type=\"hdrfilm\"><rfilter type=\"gaussian\"><float name=\"stddev\" value=\"0\"/></rfilter></film>", {"stddev"});
  bad("<film type=\"hdrfilm\"><rfilter type=\"mitchell\"/></film>", {"unknown plugin 'mitchell'"});
  bad("<film type=\"hdrfilm\"><rfilter type=\"tent\"><float name=\"radius\" value=\"0\"/></rfilter></film>", {"'radius'"});
  bad("<film type=\"hdrfilm\"><string name=\"file_format\" value=\"png\"/></film>", {"'file_format' must be one of"});
  bad("<film type=\"hdrfilm\"><string name=\"pixel_format\" value=\"rgbx\"/></film>", {"'pixel_format' must be one of"});
  bad("<film type=\"ldrfilm\"/>", {"unknown plugin 'ldrfilm'"});
  bad("<sampler type=\"independent\"><integer name=\"sample_count\" value=\"0\"/></sampler>", {"'sample_count' must be positive"});
  bad("<sampler type=\"independent\"><integer name=\"seed\" value=\"-1\"/></sampler>", {"'seed'"});
  bad("<sampler type=\"halton\"/>", {"unknown plugin 'halton'", "known: independent, ldsampler"});
  bad("<sampler type=\"ldsampler\"><integer name=\"sample_count\" value=\"-2\"/></sampler>", {"'sample_count' must be positive"});
  bad("<sampler type=\"ldsampler\"><float name=\"jitter\" value=\"1\"/></sampler>", {"unsupported parameter 'jitter'"});
  bad("<float name=\"fov\" value=\"40\"/><string name=\"focal_length\" value=\"50mm\"/>", {"either 'fov' or 'focal_length'"});
  bad("<string name=\"focal_length\" value=\"fifty\"/>", {"'focal_length' must be a positive length"});
  bad("<float name=\"focal_length\" value=\"50\"/>", {"focal_length"});
  bad("<shape type=\"cube\"/>", {"unexpected <shape> inside <sensor>"});
  expectError([&] { loadText(dir, sceneXml("", "<sensor type=\"orthographic\"/>")); }, {"unknown plugin 'orthographic'"});
  expectError([&] { loadText(dir, sceneXml("<sensor type=\"perspective\"/>")); }, {"only one sensor"});
}

TEST(SceneIntegrator, PathAndRcacheParameters) {
  TempDir dir;
  const Scene p = loadText(dir, sceneXml("<integrator type=\"path\"><integer name=\"max_depth\" value=\"6\"/>"
                                         "<integer name=\"rr_depth\" value=\"3\"/><boolean name=\"hide_emitters\" value=\"true\"/></integrator>"));
  EXPECT_EQ(p.integrator.type, "path");
  EXPECT_EQ(p.integrator.maxDepth, 6);
  EXPECT_EQ(p.integrator.rrDepth, 3);
  EXPECT_TRUE(p.integrator.hideEmitters);
  EXPECT_EQ(p.integrator.props.getInt("max_depth", 0), 6);
  EXPECT_TRUE(p.integrator.props.unusedNames().size() == 2u);  // read above: max_depth only
  const Scene r = loadText(dir, sceneXml("<integrator type=\"rcache\"><float name=\"a\" value=\"0.2\"/><integer name=\"rays\" value=\"1024\"/></integrator>"));
  EXPECT_EQ(r.integrator.type, "rcache");
  EXPECT_EQ(r.integrator.maxDepth, -1);
  EXPECT_EQ(r.integrator.props.getInt("rays", 0), 1024);
}

TEST(SceneIntegrator, Errors) {
  TempDir dir;
  expectError([&] { loadText(dir, sceneXml("<integrator type=\"path\">\n<integer name=\"max_depth\" value=\"-2\"/></integrator>")); },
              {"scene.xml:4:", "max_depth"});
  expectError([&] { loadText(dir, sceneXml("<integrator type=\"path\"><integer name=\"rr_depth\" value=\"0\"/></integrator>")); }, {"rr_depth"});
  expectError([&] { loadText(dir, sceneXml("<integrator type=\"path\"/><integrator type=\"path\"/>")); }, {"only one <integrator>"});
  expectError([&] { loadText(dir, sceneXml("<integrator type=\"rcache\"><transform name=\"to_world\"/></integrator>")); },
              {"unsupported parameter 'to_world'"});
}

// Mitsuba attaches a top-level area emitter to every shape that refers to it, also before its
// definition in the file.
TEST(SceneEmitters, SharedAreaEmitterByReference) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("<shape type=\"rectangle\"><ref id=\"glow\"/></shape>"
                                         "<shape type=\"sphere\"><bsdf type=\"diffuse\"/><ref id=\"glow\"/></shape>"
                                         "<emitter type=\"area\" id=\"glow\"><rgb name=\"radiance\" value=\"2\"/></emitter>"));
  ASSERT_EQ(s.emitters.size(), 2u);
  EXPECT_EQ(s.emitters[0].mesh, 0);
  EXPECT_EQ(s.emitters[1].sphere, 0);
  EXPECT_EQ(s.emitters[1].radiance, Color(2.0f));
  expectError([&] { loadText(dir, sceneXml("<emitter type=\"area\"/>")); }, {"must be nested inside a <shape>"});
}

}  // namespace
}  // namespace rc::test
