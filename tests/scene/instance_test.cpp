// Mitsuba's `shapegroup` and `instance` (src/shapes/shapegroup.cpp, instance.cpp) and the
// sdfgrid's parameters: a group is not rendered, each instance places a copy equal to the group's
// shapes transformed by hand (normals made in the group's space, then the inverse transpose), and
// what Mitsuba refuses — emitters or nested groups in a group, an instance without a group — is an
// error naming file:line, as are malformed grids.
#include <gtest/gtest.h>

#include "common/vol_file_bytes.h"
#include "geometry/face_normal.h"
#include "scene_test_util.h"

namespace rc::test {
namespace {

// A tetrahedron-like open mesh with uvs, written with and without vertex normals.
const std::string kObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
    "f 1/1 3/3 2/2\nf 1/1 2/2 4/4\nf 1/1 4/4 3/3\nf 2/2 3/3 4/4\n";
const std::string kObjWithNormals =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvn -1 -1 -1\nvn 1 0.2 0\nvn 0 1 0.3\nvn 0.1 0 1\n"
    "f 1/1/1 3/3/3 2/2/2\nf 1/1/1 2/2/2 4/4/4\nf 1/1/1 4/4/4 3/3/3\nf 2/2/2 3/3/3 4/4/4\n";

// The group's own placement of the mesh (a non-uniform scale and a rotation), and instance
// matrices (Mitsuba's <matrix>, row-major): a non-uniform scale with a shear and a translation, and
// a mirroring one.
const std::string kShapeToWorld = "<scale value=\"1, 2, 0.5\"/><rotate y=\"1\" angle=\"20\"/>";
const float kGeneral[16] = {3, 0.5f, 0, 1, 0, 1, -0.7f, -2, 0.2f, 0, 0.25f, 4, 0, 0, 0, 1};
const float kMirror[16] = {-2, 0, 0, 0, 0, 1, 0, 0.5f, 0, 0, 1.5f, 0, 0, 0, 0, 1};

std::string matrixXml(const float* rowMajor) {
  std::string v;
  for (int i = 0; i < 16; ++i) v += (i ? " " : "") + std::to_string(rowMajor[i]);
  return "<matrix value=\"" + v + "\"/>";
}
Mat4 matrixOf(const float* rowMajor) {
  Mat4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = rowMajor[4 * r + c];
  return m;
}

std::string groupXml(const std::string& file) {
  return "<shape type=\"shapegroup\" id=\"g\"><shape type=\"obj\"><string name=\"filename\" value=\"" + file +
         "\"/><transform name=\"to_world\">" + kShapeToWorld + "</transform></shape></shape>\n";
}
std::string instanceXml(const std::string& transform) {
  return "<shape type=\"instance\"><ref id=\"g\"/><transform name=\"to_world\">" + transform + "</transform></shape>\n";
}

void expectNearVec(const Vec3& a, const Vec3& b, float tol, const std::string& what) {
  EXPECT_LT(glm::length(a - b), tol * std::max(1.0f, glm::length(b))) << what;
}

TEST(Instance, TheGroupIsNotRenderedAndEachInstancePlacesACopy) {
  TempDir dir;
  dir.write("m.obj", kObj);
  const Scene none = loadText(dir, sceneXml(groupXml("m.obj")));
  EXPECT_TRUE(none.meshes.empty());
  const Scene two = loadText(dir, sceneXml(groupXml("m.obj") + instanceXml("<translate x=\"5\"/>") + instanceXml("")));
  ASSERT_EQ(two.meshes.size(), 2u);
  for (size_t i = 0; i < two.meshes[0].positions.size(); ++i)
    expectNearVec(two.meshes[0].positions[i], two.meshes[1].positions[i] + Vec3(5, 0, 0), 1e-6f, "translated copy");
  EXPECT_NE(two.meshes[0].name.find(" in instance#"), std::string::npos) << two.meshes[0].name;
}

// Instance placement = the group's mesh (loaded as a plain shape with the group's to_world)
// transformed by the instance's matrix by hand: points by M, normals by M's inverse transpose (so
// normals the group computed are bent as Mitsuba's instance bends them), uvs kept, the winding
// reversed by a mirror, so the face normal still agrees with the normals.
void expectInstanceIsTheMeshTransformedByHand(const std::string& obj, const float* instanceMatrix) {
  TempDir dir;
  dir.write("m.obj", obj);
  const Scene inGroup = loadText(dir, sceneXml(groupXml("m.obj") + instanceXml(matrixXml(instanceMatrix))));
  const Scene plain = loadText(dir, sceneXml("<shape type=\"obj\"><string name=\"filename\" value=\"m.obj\"/>"
                                             "<transform name=\"to_world\">" + kShapeToWorld + "</transform></shape>"));
  const Mesh& placed = inGroup.meshes.at(0);
  const Mesh& base = plain.meshes.at(0);
  const Mat4 m = matrixOf(instanceMatrix);
  const Mat3 normalMatrix = glm::transpose(glm::inverse(Mat3(m)));
  const bool mirrored = glm::determinant(Mat3(m)) < 0.0f;
  ASSERT_EQ(placed.positions.size(), base.positions.size());
  ASSERT_EQ(placed.normals.size(), base.normals.size());
  ASSERT_EQ(placed.triangles.size(), base.triangles.size());
  for (size_t i = 0; i < base.positions.size(); ++i) {
    expectNearVec(placed.positions[i], Vec3(m * Vec4(base.positions[i], 1.0f)), 1e-6f, "position");
    expectNearVec(placed.normals[i], glm::normalize(normalMatrix * base.normals[i]), 1e-6f, "normal");
    EXPECT_EQ(placed.uvs[i], base.uvs[i]);
  }
  for (size_t t = 0; t < base.triangles.size(); ++t) {
    const glm::uvec3 b = base.triangles[t];
    EXPECT_EQ(placed.triangles[t], mirrored ? glm::uvec3(b.x, b.z, b.y) : b);
    // The face normal (from the winding) on the side of the placed vertex normals.
    const Vec3 n = placed.normals[b.x] + placed.normals[b.y] + placed.normals[b.z];
    EXPECT_GT(glm::dot(orientedFaceNormal(placed, t), n), 0.0f);
    const glm::uvec3 w = placed.triangles[t];
    EXPECT_GT(glm::dot(unitTriangleNormal(placed.positions[w.x], placed.positions[w.y], placed.positions[w.z]), n), 0.0f);
  }
}

TEST(Instance, PlacesTheGroupsMeshAsTransformedByHand) {
  expectInstanceIsTheMeshTransformedByHand(kObjWithNormals, kGeneral);
  expectInstanceIsTheMeshTransformedByHand(kObj, kGeneral);  // normals made in the group's space
  expectInstanceIsTheMeshTransformedByHand(kObj, kMirror);
}

TEST(Instance, AnalyticShapesAndGridsArePlaced) {
  TempDir dir;
  dir.write("c.txt", "0 0 0 0.1\n1 0 0 0.2\n");
  dir.write("g.vol", volGrid(2, 2, 2, [](int i, int, int) { return i ? 1.0f : -1.0f; }));
  const Scene s = loadText(dir, sceneXml(
      "<shape type=\"shapegroup\" id=\"g\">"
      "<shape type=\"sphere\"><point name=\"center\" value=\"1, 0, 0\"/><float name=\"radius\" value=\"0.5\"/></shape>"
      "<shape type=\"cylinder\"/>"
      "<shape type=\"linearcurve\"><string name=\"filename\" value=\"c.txt\"/></shape>"
      "<shape type=\"sdfgrid\"><string name=\"filename\" value=\"g.vol\"/></shape></shape>" +
      instanceXml("<scale value=\"2\"/><rotate z=\"1\" angle=\"90\"/><translate z=\"3\"/>")));
  ASSERT_EQ(s.spheres.size(), 1u);
  ASSERT_EQ(s.cylinders.size(), 1u);
  ASSERT_EQ(s.curves.size(), 1u);
  ASSERT_EQ(s.sdfGrids.size(), 1u);
  // (1,0,0) scaled by 2, turned 90° about z, raised by 3: (0, 2, 3); radii scale with the map.
  expectNearVec(s.spheres[0].center, Vec3(0, 2, 3), 1e-6f, "sphere centre");
  EXPECT_NEAR(s.spheres[0].radius, 1.0f, 1e-6f);
  expectNearVec(Vec3(s.curves[0].points[1]), Vec3(0, 2, 3), 1e-6f, "curve point");
  EXPECT_NEAR(s.curves[0].points[1].w, 0.4f, 1e-6f);
  expectNearVec(Vec3(s.cylinders[0].toWorld * Vec4(0, 0, 1, 1)), Vec3(0, 0, 5), 1e-6f, "cylinder top");
  expectNearVec(Vec3(s.sdfGrids[0].toWorld * Vec4(1, 0, 0, 1)), Vec3(0, 2, 3), 1e-6f, "grid corner");
  EXPECT_FALSE(s.cylinders[0].flipNormals);
  // A mirroring instance flips the cylinder's cross-product normal back to Mitsuba's.
  const Scene mirrored = loadText(dir, sceneXml("<shape type=\"shapegroup\" id=\"g\"><shape type=\"cylinder\"/></shape>" +
                                                instanceXml("<scale x=\"-1\"/>")));
  EXPECT_TRUE(mirrored.cylinders.at(0).flipNormals);
}

TEST(Instance, WhatMitsubaRefusesIsAnErrorWithFileAndLine) {
  TempDir dir;
  dir.write("m.obj", kObj);
  const std::string group = groupXml("m.obj");
  expectError([&] { loadText(dir, sceneXml("<shape type=\"instance\"/>")); },
              {"scene.xml:3:", "<shape type=\"instance\">", "needs a shapegroup"});
  expectError([&] { loadText(dir, sceneXml("<bsdf type=\"diffuse\" id=\"b\"/>\n<shape type=\"instance\"><ref id=\"b\"/></shape>")); },
              {"scene.xml:4:", "id 'b'", "is not a shapegroup"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"instance\"><ref id=\"nowhere\"/></shape>")); },
              {"scene.xml:3:", "unknown id 'nowhere'"});
  expectError([&] { loadText(dir, sceneXml(group + "<shape type=\"instance\"><ref id=\"g\"/>\n<ref id=\"g\"/></shape>")); },
              {"scene.xml:5:", "one shapegroup, this is the second"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"shapegroup\" id=\"e\">\n<shape type=\"sphere\">\n"
                                           "<emitter type=\"area\"/></shape></shape>")); },
              {"scene.xml:5:", "emitter", "cannot instance emitters"});
  expectError([&] { loadText(dir, sceneXml(group + "<shape type=\"shapegroup\" id=\"n\">\n<shape type=\"instance\">"
                                           "<ref id=\"g\"/></shape></shape>")); },
              {"scene.xml:5:", "instance inside the shapegroup", "no nesting"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"shapegroup\" id=\"n\">\n<shape type=\"shapegroup\"/></shape>")); },
              {"scene.xml:4:", "shapegroup inside the shapegroup"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"shapegroup\" id=\"n\">\n<bsdf type=\"diffuse\"/></shape>")); },
              {"scene.xml:4:", "holds only shapes"});
  expectError([&] { loadText(dir, sceneXml(group + instanceXml("<scale x=\"0\"/>"))); },
              {"scene.xml:4:", "singular"});
  // What a placed copy cannot represent.
  expectError([&] { loadText(dir, sceneXml("<shape type=\"shapegroup\" id=\"s\"><shape type=\"sphere\"/></shape>\n"
                                           "<shape type=\"instance\"><ref id=\"s\"/><transform name=\"to_world\">"
                                           "<scale value=\"1, 2, 1\"/></transform></shape>")); },
              {"scene.xml:4:", "ellipsoid"});
}

TEST(Instance, TheCopiesAreBoundedBeforeTheyAreMade) {
  // 2^18 occupied voxels (signs alternate, so every voxel changes sign) shared by every copy: the
  // 129th instance would pass 2^25 primitives in all.
  TempDir dir;
  dir.write("g.vol", volGrid(65, 65, 65, [](int i, int j, int k) { return (i + j + k) % 2 ? 1.0f : -1.0f; }));
  std::string xml = "<shape type=\"shapegroup\" id=\"g\"><shape type=\"sdfgrid\"><string name=\"filename\" value=\"g.vol\"/></shape></shape>";
  for (int i = 0; i < 128; ++i) xml += "<shape type=\"instance\"><ref id=\"g\"/></shape>";
  EXPECT_EQ(loadText(dir, sceneXml(xml)).sdfGrids.size(), 128u);
  expectError([&] { loadText(dir, sceneXml(xml + "\n<shape type=\"instance\"><ref id=\"g\"/></shape>")); },
              {"scene.xml:4:", "more than 33554432 primitives"});
}

TEST(SdfGridLoad, MalformedGridsAndParametersAreErrors) {
  TempDir dir;
  auto sdf = [&](const std::string& bytes, const std::string& params = "") {
    dir.write("g.vol", bytes);
    return loadText(dir, sceneXml("<shape type=\"sdfgrid\"><string name=\"filename\" value=\"g.vol\"/>" + params + "</shape>"));
  };
  const auto ramp = [](int i, int, int) { return i ? 1.0f : -1.0f; };
  VolBytes threeChannels = volHeader(2, 2, 2, 3);
  for (int i = 0; i < 24; ++i) threeChannels.f32(i % 2 ? 1.0f : -1.0f);
  expectError([&] { sdf(threeChannels.s); }, {"scene.xml:3:", "g.vol", "1 channel", "has 3"});
  expectError([&] { sdf(volGrid(2, 1, 2, ramp)); }, {"scene.xml:3:", "at least 2 samples", "has 1 along y"});
  expectError([&] { sdf(volGrid(2, 2, 2, [](int, int, int) { return 0.5f; })); }, {"scene.xml:3:", "no voxel", "change sign"});
  expectError([&] { sdf(volGrid(2, 2, 2, ramp), "<string name=\"normals\" value=\"flat\"/>"); },
              {"scene.xml:3:", "'smooth' or 'analytic'", "'flat'"});
  expectError([&] { sdf(volGrid(2, 2, 2, ramp), "<boolean name=\"flip_normals\" value=\"true\"/>"); },
              {"scene.xml:3:", "flip_normals"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"sdfgrid\"/>")); }, {"scene.xml:3:", "missing parameter 'filename'"});
  expectError([&] { sdf(volGrid(2, 2, 2, ramp), "<emitter type=\"area\"/>"); }, {"scene.xml:3:", "area emitter on a sdfgrid"});
  expectError([&] { sdf(volGrid(2, 2, 2, ramp), "<medium type=\"homogeneous\" name=\"interior\"/>"); },
              {"scene.xml:3:", "media inside an sdfgrid are not supported"});
  const Scene ok = sdf(volGrid(3, 2, 2, ramp), "<string name=\"normals\" value=\"analytic\"/>");
  ASSERT_EQ(ok.sdfGrids.size(), 1u);
  EXPECT_FALSE(ok.sdfGrids[0].smoothNormals);
  EXPECT_EQ(ok.sdfGrids[0].voxels->size(), 1u);  // samples −1, 1, 1 along x: only the first voxel changes sign
}

}  // namespace
}  // namespace rc::test
