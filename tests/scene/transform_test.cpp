// <transform>: each operation, composition order, lookat, error paths, and how shapes use it
// (positions by M, normals by the inverse transpose).
#include <glm/gtc/matrix_transform.hpp>

#include "scene_test_util.h"

namespace rc::test {
namespace {

// Loads a rectangle with the given transform body and returns its world positions.
Mesh rectangleWith(const TempDir& dir, const std::string& ops) {
  const Scene s = loadText(dir, sceneXml("<shape type=\"rectangle\"><transform name=\"to_world\">" + ops + "</transform></shape>"));
  return s.meshes.at(0);
}

// Transforms are built in float; 1e-5 absolute covers a few ulps of the unit-sized values here.
constexpr float kTol = 1e-5f;

void expectVec(const Vec3& a, const Vec3& b, float tol = kTol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(SceneTransform, TranslateForms) {
  TempDir dir;
  expectVec(rectangleWith(dir, "<translate x=\"1\" y=\"2\" z=\"3\"/>").positions[0], Vec3(0, 1, 3));
  expectVec(rectangleWith(dir, "<translate value=\"1, 2, 3\"/>").positions[0], Vec3(0, 1, 3));
  expectVec(rectangleWith(dir, "<translate z=\"5\"/>").positions[2], Vec3(1, 1, 5));
}

TEST(SceneTransform, ScaleForms) {
  TempDir dir;
  expectVec(rectangleWith(dir, "<scale value=\"2\"/>").positions[2], Vec3(2, 2, 0));
  expectVec(rectangleWith(dir, "<scale x=\"3\"/>").positions[2], Vec3(3, 1, 0));
  expectVec(rectangleWith(dir, "<scale value=\"2, 4, 1\"/>").positions[2], Vec3(2, 4, 0));
}

TEST(SceneTransform, RotateIsRightHandedInDegrees) {
  TempDir dir;
  // +90° about z takes +x to +y: vertex (1,-1,0) → (1,1,0).
  expectVec(rectangleWith(dir, "<rotate z=\"1\" angle=\"90\"/>").positions[1], Vec3(1, 1, 0));
  expectVec(rectangleWith(dir, "<rotate axis=\"0, 0, 1\" angle=\"90\"/>").positions[1], Vec3(1, 1, 0));
  // -90° about x turns the +z normal into +y (a floor facing up).
  const Mesh m = rectangleWith(dir, "<rotate x=\"1\" angle=\"-90\"/>");
  expectVec(m.normals[0], Vec3(0, 1, 0));
}

TEST(SceneTransform, MatrixRowMajor16And9) {
  TempDir dir;
  // Row-major: the translation is the last column of the first three rows.
  expectVec(rectangleWith(dir, "<matrix value=\"1 0 0 5  0 1 0 6  0 0 1 7  0 0 0 1\"/>").positions[0], Vec3(4, 5, 7));
  // A 3×3 that swaps x and y: (1,-1,0) → (-1,1,0).
  expectVec(rectangleWith(dir, "<matrix value=\"0,1,0, 1,0,0, 0,0,1\"/>").positions[1], Vec3(-1, 1, 0));
}

TEST(SceneTransform, ChildrenComposeInTheOrderWritten) {
  TempDir dir;
  // scale then translate: (1,1,0)·2 + (10,0,0) = (12,2,0); translate then scale: (11,1,0)·2 = (22,2,0).
  expectVec(rectangleWith(dir, "<scale value=\"2\"/><translate x=\"10\"/>").positions[2], Vec3(12, 2, 0));
  expectVec(rectangleWith(dir, "<translate x=\"10\"/><scale value=\"2\"/>").positions[2], Vec3(22, 2, 0));
  // rotate 90° about z then translate x: (1,-1,0) → (1,1,0) → (11,1,0).
  expectVec(rectangleWith(dir, "<rotate z=\"1\" angle=\"90\"/><translate x=\"10\"/>").positions[1], Vec3(11, 1, 0));
  expectVec(rectangleWith(dir, "<translate x=\"10\"/><rotate z=\"1\" angle=\"90\"/>").positions[1], Vec3(1, 11, 0));
}

TEST(SceneTransform, LookAtMatchesMitsubaFrame) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("", "<sensor type=\"perspective\"><transform name=\"to_world\">"
                                             "<lookat origin=\"0, 1, 5\" target=\"0, 1, 0\" up=\"0, 1, 0\"/></transform></sensor>"));
  const Mat4& m = s.camera.toWorld;
  expectVec(Vec3(m[3]), Vec3(0, 1, 5));   // origin
  expectVec(Vec3(m[2]), Vec3(0, 0, -1));  // local +z looks at the target
  expectVec(Vec3(m[1]), Vec3(0, 1, 0));   // local +y is up
  expectVec(Vec3(m[0]), Vec3(-1, 0, 0));  // local +x = up × dir (Mitsuba: "left")
}

TEST(SceneTransform, LookAtWithSkewUpIsOrthonormalised) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("", "<sensor type=\"perspective\"><transform name=\"to_world\">"
                                             "<lookat origin=\"1, 2, 3\" target=\"4, 0, -1\" up=\"0.3, 1, 0.2\"/></transform></sensor>"));
  const Mat3 r(s.camera.toWorld);
  const Mat3 rtr = glm::transpose(r) * r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(rtr[i][j], i == j ? 1.0f : 0.0f, kTol);
  expectVec(Vec3(s.camera.toWorld[2]), glm::normalize(Vec3(3, -2, -4)));
  EXPECT_GT(glm::dot(Vec3(s.camera.toWorld[1]), Vec3(0.3f, 1, 0.2f)), 0.0f);
}

TEST(SceneTransform, NormalsUseTheInverseTranspose) {
  TempDir dir;
  // A rectangle tilted 45° about y then squashed in x: the normal must stay perpendicular to
  // the transformed surface, which a plain M·n would not.
  const Mesh m = rectangleWith(dir, "<rotate y=\"1\" angle=\"45\"/><scale x=\"0.25\"/>");
  const Vec3 e1 = m.positions[1] - m.positions[0], e2 = m.positions[3] - m.positions[0];
  const Vec3 geometric = glm::normalize(glm::cross(e1, e2));
  for (const Vec3& n : m.normals) {
    EXPECT_NEAR(glm::length(n), 1.0f, kTol);
    EXPECT_NEAR(glm::dot(n, e1), 0.0f, kTol);
    EXPECT_NEAR(glm::dot(n, e2), 0.0f, kTol);
    EXPECT_NEAR(glm::dot(n, geometric), 1.0f, kTol);  // same side as the winding
  }
  const Vec3 naive = glm::normalize(Vec3(0.25f * std::sqrt(0.5f), 0, std::sqrt(0.5f)));
  EXPECT_GT(glm::length(m.normals[0] - naive), 0.1f);  // the test would catch M·n
}

TEST(SceneTransform, MirrorKeepsWindingAndNormalsAgreeing) {
  TempDir dir;
  const Mesh m = rectangleWith(dir, "<scale z=\"-1\"/>");
  expectVec(m.normals[0], Vec3(0, 0, -1));
  const glm::uvec3 t = m.triangles[0];
  const Vec3 g = glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]);
  EXPECT_LT(g.z, 0.0f);
}

TEST(SceneTransform, Errors) {
  TempDir dir;
  auto bad = [&](const std::string& ops, std::initializer_list<std::string> parts) {
    expectError([&] { rectangleWith(dir, "\n" + ops); }, parts);
  };
  bad("<translate x=\"nan\"/>", {"scene.xml:4:", "<translate>", "not a finite number"});
  bad("<scale value=\"1e30\"/><scale value=\"1e30\"/>", {"not finite"});
  bad("<rotate x=\"1\"/>", {"missing attribute 'angle'"});
  bad("<rotate angle=\"30\"/>", {"rotation axis is zero"});
  bad("<matrix value=\"1 2 3 4\"/>", {"16 or 9 numbers"});
  bad("<lookat origin=\"0 0 0\" target=\"0 0 0\"/>", {"coincide"});
  bad("<lookat origin=\"0 0 0\" target=\"0 1 0\" up=\"0 1 0\"/>", {"parallel"});
  bad("<lookat origin=\"0 0 0\"/>", {"needs 'origin' and 'target'"});
  bad("<shear value=\"1\"/>", {"unknown transform operation <shear>"});
  bad("<translate x=\"1\" value=\"1 2 3\"/>", {"either 'value' or x/y/z"});
  bad("<translate w=\"1\"/>", {"unsupported attribute 'w'"});
}

}  // namespace
}  // namespace rc::test
