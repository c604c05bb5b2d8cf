// The integrator registry: names, parameter lists for -D routing, aliases (volpath), direct's counts,
// unknown types and unused parameters with their locations, and nested integrators.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "app/integrator_registry.h"
#include "core/error.h"
#include "scene/param_reader.h"
#include "scene/scene_loader.h"

namespace rc {
namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

std::string errorOf(IntegratorSettings s, bool lenient = false, std::vector<std::string>* warnings = nullptr) {
  try {
    makeIntegrator(std::move(s), lenient, true, warnings);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

Scene loadIntegratorXml(const std::string& integratorXml) {
  // One folder per process: ctest runs this file's tests as parallel processes.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("rc_registry_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "scene.xml").string();
  std::ofstream(path) << "<scene version=\"3.0.0\">\n"
                       << integratorXml << "\n<sensor type=\"perspective\"/>\n</scene>\n";
  return loadScene(path, LoadOptions{}, nullptr);
}

TEST(IntegratorRegistry, ParameterNamesRouteDefines) {
  const auto path = integratorParameterNames("path");
  EXPECT_TRUE(contains(path, "max_depth"));
  EXPECT_TRUE(contains(path, "rr_depth"));
  EXPECT_FALSE(contains(path, "rays"));  // -D rays=... is a scene parameter for path
  const auto rcache = integratorParameterNames("rcache");
  for (const char* n : {"max_depth", "a", "rays", "order", "frame", "mode", "share_pixel", "light_samples"})
    EXPECT_TRUE(contains(rcache, n)) << n;
  EXPECT_EQ(integratorParameterNames("volpath"), path);
  EXPECT_TRUE(contains(integratorParameterNames("direct"), "emitter_samples"));
  EXPECT_FALSE(contains(integratorParameterNames("direct"), "max_depth"));
  EXPECT_TRUE(integratorParameterNames("bdpt").empty());
}

// Mitsuba's differentiable path tracers render path's primal image: max_depth defaults to 6 in
// their base class (ad/integrators/common.py), direct_projective forces 2; the projective ones'
// gradient settings are accepted, and prb does not take them.
TEST(IntegratorRegistry, DifferentiableIntegratorsAreTheirPrimalPathTracer) {
  for (const char* name : {"prb", "prb_basic", "prb_projective", "prbvolpath"}) {
    IntegratorSettings st;
    ParamReader none(nullptr);
    findIntegrator(name)->readParams(none, st);
    EXPECT_EQ(st.maxDepth, 6) << name;
    EXPECT_EQ(st.rrDepth, 5) << name;
  }
  IntegratorSettings direct;
  ParamReader none(nullptr);
  findIntegrator("direct_projective")->readParams(none, direct);
  EXPECT_EQ(direct.maxDepth, 2);
  EXPECT_TRUE(contains(integratorParameterNames("prb_projective"), "guiding"));
  EXPECT_FALSE(contains(integratorParameterNames("prb"), "sppc"));

  const Scene projective = loadIntegratorXml(
      "<integrator type=\"direct_projective\"><integer name=\"max_depth\" value=\"7\"/>"
      "<integer name=\"sppc\" value=\"32\"/><string name=\"guiding\" value=\"grid\"/></integrator>");
  EXPECT_EQ(errorOf(projective.integrator), "");
  const Scene wrongGuide = loadIntegratorXml(
      "<integrator type=\"prb_projective\"><string name=\"guiding\" value=\"kdtree\"/></integrator>");
  EXPECT_NE(errorOf(wrongGuide.integrator).find("guiding"), std::string::npos);
  const Scene prbWithSppc =
      loadIntegratorXml("<integrator type=\"prb\"><integer name=\"sppc\" value=\"32\"/></integrator>");
  EXPECT_NE(errorOf(prbWithSppc.integrator).find("sppc"), std::string::npos);
}

TEST(IntegratorRegistry, MakesEveryEntry) {
  for (const IntegratorEntry& e : integratorEntries()) {
    IntegratorSettings s;
    s.type = e.name;
    const IntegratorEntry* chosen = nullptr;
    auto integ = makeIntegrator(s, false, true, nullptr, &chosen);
    ASSERT_TRUE(integ) << e.name;
    EXPECT_EQ(chosen, &e);
  }
}

TEST(IntegratorRegistry, UnknownTypeAndUnusedParameterAreLocated) {
  Scene s = loadIntegratorXml("<integrator type=\"bdpt\"/>");
  const std::string unknown = errorOf(s.integrator);
  EXPECT_NE(unknown.find("scene.xml:2"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("unknown integrator 'bdpt'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("rcache"), std::string::npos) << unknown;  // lists the known ones
  std::vector<std::string> warnings;
  EXPECT_EQ(errorOf(s.integrator, true, &warnings), "");
  ASSERT_EQ(warnings.size(), 1u);

  s = loadIntegratorXml("<integrator type=\"path\">\n<float name=\"a\" value=\"0.3\"/></integrator>");
  const std::string unused = errorOf(s.integrator);
  EXPECT_NE(unused.find("scene.xml:3"), std::string::npos) << unused;
  EXPECT_NE(unused.find("unsupported parameter 'a'"), std::string::npos) << unused;
  // The same parameter is rcache's own.
  s.integrator.type = "rcache";
  EXPECT_EQ(errorOf(s.integrator), "");
}

TEST(IntegratorRegistry, ValuesAreCheckedWhereWritten) {
  Scene s = loadIntegratorXml("<integrator type=\"rcache\">\n<integer name=\"rays\" value=\"4\"/></integrator>");
  const std::string m = errorOf(s.integrator);
  EXPECT_NE(m.find("scene.xml:3"), std::string::npos) << m;
  EXPECT_NE(m.find("'rays'"), std::string::npos) << m;
  IntegratorSettings text;
  text.type = "rcache";
  text.props.set("frame", textProperty("sideways"));
  EXPECT_NE(errorOf(text).find("must be one of auto, world, record"), std::string::npos);
  text.props.set("frame", textProperty("record"));
  text.props.set("a", textProperty("0.3"));  // -D values arrive as text and are parsed as the read asks
  EXPECT_EQ(errorOf(text), "");
}

TEST(IntegratorRegistry, DirectReadsMitsubasSampleCounts) {
  IntegratorSettings s;
  s.type = "direct";
  s.props.set("hide_emitters", textProperty("true"));
  ParamReader in(&s.props);
  findIntegrator("direct")->readParams(in, s);
  EXPECT_EQ(s.maxDepth, 2);
  EXPECT_GT(s.rrDepth, 2);  // no Russian roulette within two segments
  EXPECT_TRUE(s.hideEmitters);
  EXPECT_EQ(s.emitterSamples, 1);
  EXPECT_EQ(s.bsdfSamples, 1);
  const auto read = [](std::initializer_list<std::pair<const char*, const char*>> params) {
    IntegratorSettings d;
    d.type = "direct";
    for (const auto& [name, value] : params) d.props.set(name, textProperty(value));
    ParamReader r(&d.props);
    findIntegrator("direct")->readParams(r, d);
    return std::pair{d.emitterSamples, d.bsdfSamples};
  };
  EXPECT_EQ(read({{"shading_samples", "3"}}), std::pair(3, 3));
  EXPECT_EQ(read({{"emitter_samples", "4"}, {"bsdf_samples", "0"}}), std::pair(4, 0));
  EXPECT_EQ(read({{"bsdf_samples", "2"}}), std::pair(1, 2));  // the other count keeps shading_samples' default
  // Mitsuba's refusals: no samples at all; shading_samples together with either count.
  IntegratorSettings none;
  none.type = "direct";
  none.props.set("emitter_samples", textProperty("0"));
  none.props.set("bsdf_samples", textProperty("0"));
  EXPECT_NE(errorOf(none).find("at least one emitter or BSDF sample"), std::string::npos) << errorOf(none);
  IntegratorSettings both;
  both.type = "direct";
  both.props.set("shading_samples", textProperty("2"));
  both.props.set("bsdf_samples", textProperty("1"));
  EXPECT_NE(errorOf(both).find("'shading_samples' sets both counts"), std::string::npos) << errorOf(both);
}

TEST(IntegratorRegistry, NestedIntegratorRendersTheInnerOne) {
  const Scene s = loadIntegratorXml(
      "<integrator type=\"aov\"><string name=\"aovs\" value=\"dd.y:depth\"/>\n"
      "<integrator type=\"moment\"><integrator type=\"path\"><integer name=\"max_depth\" value=\"4\"/></integrator>"
      "</integrator></integrator>");
  EXPECT_EQ(s.integrator.type, "path");
  EXPECT_EQ(s.integrator.maxDepth, 4);
  ASSERT_EQ(s.integrator.wrappers.size(), 2u);
  EXPECT_EQ(s.integrator.wrappers[0], "aov");
  EXPECT_EQ(s.integrator.wrappers[1], "moment");
  EXPECT_EQ(errorOf(s.integrator), "");
}

}  // namespace
}  // namespace rc
