// mesh_attribute through both integrators: a PLY square under a constant white sky, seen head-on,
// has radiance ρ(x) = its reflectance at x (a diffuse surface reflects E/π·ρ with E = π), so the
// image shows the attribute itself: vertex colours blended linearly, face colours per triangle.
#include <gtest/gtest.h>

#include "scene/scene_test_util.h"
#include "test_scene.h"

namespace rc {
namespace {

// The unit square [−1, 1]² at z = 0 as two triangles (0 1 2) and (0 2 3), with vertex colours
// whose blend is linear over the whole square (v0 + v2 = v1 + v3) and one colour per face.
const char* kPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "property float color_0\nproperty float color_1\nproperty float color_2\n"
    "element face 2\nproperty list uchar int vertex_indices\nproperty float r\nproperty float g\nproperty float b\n"
    "end_header\n"
    "-1 -1 0 0.1 0.2 0.3\n1 -1 0 0.5 0.2 0.1\n1 1 0 0.9 0.6 0.5\n-1 1 0 0.5 0.6 0.7\n"
    "3 0 1 2 0.8 0.1 0.1\n3 0 2 3 0.1 0.1 0.8\n";

Scene squareScene(const test::TempDir& dir, const std::string& attribute) {
  dir.write("square.ply", kPly);
  // 30° field of view from z = 3: the view stays inside the square (half-width 3·tan 15° = 0.8).
  return test::loadText(dir, test::sceneXml(
      "<emitter type=\"constant\"><rgb name=\"radiance\" value=\"1\"/></emitter>"
      "<shape type=\"ply\"><string name=\"filename\" value=\"square.ply\"/><bsdf type=\"diffuse\">"
      "<texture type=\"mesh_attribute\" name=\"reflectance\"><string name=\"name\" value=\"" + attribute + "\"/>"
      "</texture></bsdf></shape>",
      "<sensor type=\"perspective\"><float name=\"fov\" value=\"30\"/><transform name=\"to_world\">"
      "<lookat origin=\"0, 0, 3\" target=\"0, 0, 0\" up=\"0, 1, 0\"/></transform>"
      "<film type=\"hdrfilm\"><integer name=\"width\" value=\"32\"/><integer name=\"height\" value=\"32\"/></film></sensor>"));
}

Color meanOf(const Image& img, int x0, int x1, int y0, int y1) {
  Color m(0.0f);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) m += img.pixels[size_t(y) * img.width + x];
  return m / float((x1 - x0) * (y1 - y0));
}

void expectNearColor(const Color& got, const Color& want, float rel, const std::string& what) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], rel * want[k]) << what << " channel " << k;
}

TEST(MeshAttributeRender, VertexColoursAreBlendedInBothIntegrators) {
  test::TempDir dir;
  const Scene s = squareScene(dir, "vertex_color");
  for (const bool cache : {false, true}) {
    const std::string name = cache ? "rcache" : "path";
    const Image img = test::renderScene(s, cache ? test::rcacheSettings(s) : test::pathSettings(s), 64, 1).image;
    // A linear function seen head-on is linear over the image: the mean is its value at the centre,
    // (v0 + v2) / 2; the left and right halves' means differ by its slope along x.
    expectNearColor(meanOf(img, 0, 32, 0, 32), Color(0.5f, 0.4f, 0.4f), 0.01f, name + " mean");
    const Color left = meanOf(img, 0, 16, 0, 32), right = meanOf(img, 16, 32, 0, 32);
    // ρ(x, y) = (0.5, 0.4, 0.4) + x·(0.2, 0, −0.1) + y·(0.2, 0.2, 0.2); the image's right half is
    // world x > 0 (Mitsuba's look_at), the halves' mean x is ±0.4.
    const Color slope = right - left;
    EXPECT_NEAR(slope.r, 0.16f, 0.016f) << name;
    EXPECT_NEAR(slope.g, 0.0f, 0.01f) << name;
    EXPECT_NEAR(slope.b, -0.08f, 0.01f) << name;
  }
}

TEST(MeshAttributeRender, FaceColoursFillTheirTriangles) {
  test::TempDir dir;
  const Scene s = squareScene(dir, "face_color");
  for (const bool cache : {false, true}) {
    const std::string name = cache ? "rcache" : "path";
    const Image img = test::renderScene(s, cache ? test::rcacheSettings(s) : test::pathSettings(s), 64, 1).image;
    // Triangle (0 1 2) lies below the diagonal y = x (image bottom right), (0 2 3) above it.
    expectNearColor(meanOf(img, 24, 32, 24, 32), Color(0.8f, 0.1f, 0.1f), 0.02f, name + " bottom right");
    expectNearColor(meanOf(img, 0, 8, 0, 8), Color(0.1f, 0.1f, 0.8f), 0.02f, name + " top left");
  }
}

}  // namespace
}  // namespace rc
