// Scene-format semantics taken from Mitsuba 3's definitions (sensor.cpp parse_fov, drjit's rotate,
// the rfilter plugins, the <path> resolver): each expected value is derived from the definition, not
// from rcache's output.
#include <cmath>

#include "render/camera.h"
#include "render/film.h"
#include "scene/scene_test_util.h"

namespace rc::test {
namespace {

std::string sensorWithFilm(int w, int h, const std::string& extra = "") {
  return "<sensor type=\"perspective\">" + extra + "<film type=\"hdrfilm\"><integer name=\"width\" value=\"" +
         std::to_string(w) + "\"/><integer name=\"height\" value=\"" + std::to_string(h) + "\"/></film></sensor>";
}

// Horizontal fov of a lens of focal length f (mm) on a 36×24 mm frame whose diagonal is mapped onto
// the image diagonal of a film with the given aspect.
double horizontalFovOfLens(double f, double aspect) {
  const double halfDiagonal = std::sqrt(36.0 * 36.0 + 24.0 * 24.0) / (2.0 * f);  // tan(diag/2)
  const double halfWidth = halfDiagonal * aspect / std::sqrt(aspect * aspect + 1.0);
  return 2.0 * std::atan(halfWidth) * 180.0 / kPiD;
}

TEST(MitsubaSemantics, DefaultFovIsA50mmLensOnTheDiagonal) {
  TempDir dir;
  for (const auto& [w, h, expected] : {std::tuple{64, 64, 34.02}, std::tuple{640, 480, 38.18}}) {
    const Scene s = loadText(dir, sceneXml("", sensorWithFilm(w, h)));
    const float aspect = float(w) / float(h);
    const float fovX = horizontalFovDegrees(s.camera.fovDegrees, s.camera.fovAxis, aspect);
    EXPECT_NEAR(fovX, horizontalFovOfLens(50.0, aspect), 1e-3) << w << "x" << h;
    EXPECT_NEAR(fovX, expected, 0.01) << w << "x" << h;  // the figures Mitsuba 3 renders with
  }
  const Scene lens = loadText(dir, sceneXml("", sensorWithFilm(64, 64, "<string name=\"focal_length\" value=\"35mm\"/>")));
  EXPECT_NEAR(horizontalFovDegrees(lens.camera.fovDegrees, lens.camera.fovAxis, 1.0f), horizontalFovOfLens(35.0, 1.0), 1e-3);
}

TEST(MitsubaSemantics, IgnoredPerspectiveParametersAreAccepted) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("", sensorWithFilm(32, 32, "<float name=\"fov\" value=\"40\"/>"
                                                                    "<float name=\"focus_distance\" value=\"6\"/>"
                                                                    "<float name=\"shutter_open\" value=\"0\"/>"
                                                                    "<float name=\"shutter_close\" value=\"1\"/>")));
  EXPECT_EQ(s.camera.fovDegrees, 40.0f);
  EXPECT_EQ(s.camera.fovAxis, "x");
}

TEST(MitsubaSemantics, PrincipalPointOffsetShiftsTheFilmSample) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("", sensorWithFilm(40, 20, "<float name=\"fov\" value=\"50\"/>"
                                                                    "<float name=\"principal_point_offset_x\" value=\"0.25\"/>"
                                                                    "<float name=\"principal_point_offset_y\" value=\"-0.1\"/>")));
  Camera plain = s.camera;
  plain.principalPointOffset = Vec2(0.0f);
  const CameraModel shifted(s.camera, 40, 20), centred(plain, 40, 20);
  // Mitsuba adds the offset (a fraction of the film) to the sample position before projecting.
  const Ray a = shifted.generate(Vec2(10.0f, 10.0f));
  const Ray b = centred.generate(Vec2(10.0f + 0.25f * 40.0f, 10.0f - 0.1f * 20.0f));
  EXPECT_NEAR(glm::length(a.d - b.d), 0.0f, 1e-6f);
}

TEST(MitsubaSemantics, ReconstructionFilters) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("", "<sensor type=\"perspective\"><film type=\"hdrfilm\">"
                                             "<string name=\"file_format\" value=\"openexr\"/><boolean name=\"banner\" value=\"false\"/>"
                                             "<string name=\"pixel_format\" value=\"rgba\"/><string name=\"component_format\" value=\"float32\"/>"
                                             "<rfilter type=\"tent\"><float name=\"radius\" value=\"1.25\"/></rfilter></film></sensor>"));
  EXPECT_EQ(s.film.filter, "tent");
  const ReconstructionFilter tent(s.film);
  EXPECT_FLOAT_EQ(tent.radius(), 1.25f);
  EXPECT_NEAR(tent.eval(0.5f), 1.0f - 0.5f / 1.25f, 1e-6f);  // Mitsuba: max(0, 1 − |x|/radius)
  EXPECT_EQ(tent.eval(1.3f), 0.0f);
  FilmSettings unit;
  unit.filter = "tent";
  EXPECT_NEAR(ReconstructionFilter(unit).eval(-0.25f), 0.75f, 1e-6f);  // default radius 1
  FilmSettings gauss;  // Mitsuba: stddev 0.5, radius 4·stddev, exp(−x²/2σ²) − exp(−r²/2σ²)
  const ReconstructionFilter g(gauss);
  EXPECT_FLOAT_EQ(g.radius(), 2.0f);
  EXPECT_NEAR(g.eval(0.5f), std::exp(-0.5f) - std::exp(-8.0f), 1e-6f);
}

// drjit's rotate uses the axis as given: R = c·I + (1 − c)·a·aᵀ + s·[a]×, so |a| ≠ 1 also scales.
TEST(MitsubaSemantics, RotateWithANonUnitAxisIsNotNormalised) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("<emitter type=\"point\"><transform name=\"to_world\">"
                                         "<translate x=\"1\"/><rotate y=\"2\" angle=\"90\"/></transform></emitter>"
                                         "<emitter type=\"point\"><transform name=\"to_world\">"
                                         "<translate y=\"1\"/><rotate value=\"0, 2, 0\" angle=\"90\"/></transform></emitter>"));
  ASSERT_EQ(s.emitters.size(), 2u);
  // a = (0,2,0), c = 0, s = 1: x̂ ↦ s·(a × x̂) = (0,0,−2); ŷ ↦ (1 − c)·|a|²·ŷ = (0,4,0).
  EXPECT_NEAR(glm::length(s.emitters[0].position - Vec3(0, 0, -2)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::length(s.emitters[1].position - Vec3(0, 4, 0)), 0.0f, 1e-5f);
}

TEST(MitsubaSemantics, PathFoldersAreSearched) {
  TempDir dir;
  dir.write("assets/meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  dir.write("scenes/inc/part.xml", "<scene version=\"3.0.0\"><shape type=\"obj\"><string name=\"filename\" value=\"meshes/tri.obj\"/></shape></scene>");
  const std::string main = dir.write("scenes/main.xml", "<scene version=\"3.0.0\"><path value=\"../assets\"/>" +
                                                            sensorWithFilm(8, 8) + "<include filename=\"inc/part.xml\"/></scene>");
  const Scene s = loadScene(main, LoadOptions{}, nullptr);
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].triangles.size(), 1u);
  const std::string bad = dir.write("scenes/bad.xml", "<scene version=\"3.0.0\">\n<path value=\"nowhere\"/>" + sensorWithFilm(8, 8) + "</scene>");
  expectError([&] { loadScene(bad, LoadOptions{}, nullptr); }, {"bad.xml:2:", "folder", "not found"});
}

}  // namespace
}  // namespace rc::test
