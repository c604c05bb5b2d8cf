// Shapes: primitives' geometry and orientation, sphere decomposition, normal policies,
// degenerate-triangle filtering, default material, mesh files through the XML.
#include "scene/mesh_builder.h"
#include "scene_test_util.h"

namespace rc::test {
namespace {

Vec3 faceNormal(const Mesh& m, size_t t) {
  const glm::uvec3 i = m.triangles[t];
  return glm::normalize(glm::cross(m.positions[i.y] - m.positions[i.x], m.positions[i.z] - m.positions[i.x]));
}

TEST(SceneShapes, RectangleFacesPlusZ) {
  TempDir dir;
  const Mesh m = loadText(dir, sceneXml("<shape type=\"rectangle\"/>")).meshes.at(0);
  EXPECT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.triangles.size(), 2u);
  for (size_t t = 0; t < 2; ++t) EXPECT_EQ(faceNormal(m, t), Vec3(0, 0, 1));
  for (const Vec3& p : m.positions) EXPECT_EQ(std::fabs(p.x) + std::fabs(p.y), 2.0f);  // corners of [-1,1]²
  EXPECT_EQ(m.uvs.size(), 4u);
}

TEST(SceneShapes, CubeIsClosedWithOutwardFlatNormals) {
  TempDir dir;
  const Mesh m = loadText(dir, sceneXml("<shape type=\"cube\"/>")).meshes.at(0);
  EXPECT_EQ(m.positions.size(), 24u);
  ASSERT_EQ(m.triangles.size(), 12u);
  float area = 0.0f;
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const glm::uvec3 i = m.triangles[t];
    const Vec3 centroid = (m.positions[i.x] + m.positions[i.y] + m.positions[i.z]) / 3.0f;
    EXPECT_GT(glm::dot(faceNormal(m, t), centroid), 0.0f) << "triangle " << t << " faces inward";
    for (int k = 0; k < 3; ++k) EXPECT_EQ(m.normals[i[k]], faceNormal(m, t));
    area += 0.5f * glm::length(glm::cross(m.positions[i.y] - m.positions[i.x], m.positions[i.z] - m.positions[i.x]));
  }
  EXPECT_FLOAT_EQ(area, 24.0f);  // six faces of 2×2
}

TEST(SceneShapes, DiskIsAFineUnitFan) {
  TempDir dir;
  const Mesh m = loadText(dir, sceneXml("<shape type=\"disk\"/>")).meshes.at(0);
  ASSERT_GE(m.triangles.size(), 64u);
  float area = 0.0f;
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    EXPECT_NEAR(glm::dot(faceNormal(m, t), Vec3(0, 0, 1)), 1.0f, 1e-6f);
    const glm::uvec3 i = m.triangles[t];
    area += 0.5f * glm::length(glm::cross(m.positions[i.y] - m.positions[i.x], m.positions[i.z] - m.positions[i.x]));
  }
  for (const Vec3& p : m.positions) EXPECT_LE(glm::length(p), 1.0f + 1e-6f);
  // A regular n-gon inscribed in the unit circle has area (n/2)·sin(2π/n); ≥128 segments is within 0.05% of π.
  EXPECT_NEAR(area, kPi, 0.0005f * kPi);
}

TEST(SceneShapes, SphereTakesUniformScaleRotationAndTranslation) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml(
      "<shape type=\"sphere\"><point name=\"center\" value=\"1, 0, 0\"/><float name=\"radius\" value=\"0.5\"/>"
      "<transform name=\"to_world\"><rotate z=\"1\" angle=\"90\"/><scale value=\"2\"/><translate x=\"10\"/></transform></shape>"
      "<shape type=\"sphere\"><boolean name=\"flip_normals\" value=\"true\"/></shape>"));
  ASSERT_EQ(s.spheres.size(), 2u);
  EXPECT_TRUE(s.meshes.empty());
  // center (1,0,0) → rotate → (0,1,0) → ×2 → (0,2,0) → +x10 → (10,2,0); radius 0.5×2.
  EXPECT_NEAR(s.spheres[0].center.x, 10.0f, 1e-5f);
  EXPECT_NEAR(s.spheres[0].center.y, 2.0f, 1e-5f);
  EXPECT_NEAR(s.spheres[0].radius, 1.0f, 1e-6f);
  EXPECT_FALSE(s.spheres[0].flipNormals);
  EXPECT_TRUE(s.spheres[1].flipNormals);
  EXPECT_EQ(s.spheres[1].radius, 1.0f);
}

TEST(SceneShapes, SphereErrors) {
  TempDir dir;
  expectError([&] { loadText(dir, sceneXml("<shape type=\"sphere\">\n<float name=\"radius\" value=\"-1\"/></shape>")); },
              {"scene.xml:4:", "<shape type=\"sphere\">", "radius must be positive"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"sphere\"><transform name=\"to_world\"><scale x=\"2\"/></transform></shape>")); },
              {"uniformly"});
}

TEST(SceneShapes, FaceAndFlipNormals) {
  TempDir dir;
  dir.write("q.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n");
  const Scene s = loadText(dir, sceneXml(
      "<shape type=\"obj\"><string name=\"filename\" value=\"q.obj\"/></shape>"
      "<shape type=\"obj\"><string name=\"filename\" value=\"q.obj\"/><boolean name=\"face_normals\" value=\"true\"/></shape>"
      "<shape type=\"obj\"><string name=\"filename\" value=\"q.obj\"/><boolean name=\"flip_normals\" value=\"true\"/></shape>"
      "<shape type=\"rectangle\"><boolean name=\"flip_normals\" value=\"true\"/></shape>"));
  EXPECT_EQ(s.meshes[0].normals.size(), 4u);
  EXPECT_TRUE(s.meshes[1].normals.empty());
  EXPECT_EQ(s.meshes[2].normals[0], Vec3(0, 0, -1));
  EXPECT_EQ(faceNormal(s.meshes[2], 0), Vec3(0, 0, -1));
  EXPECT_EQ(faceNormal(s.meshes[3], 0), Vec3(0, 0, -1));
  EXPECT_EQ(s.meshes[3].normals[0], Vec3(0, 0, -1));
}

TEST(SceneShapes, MissingNormalsAreAngleWeighted) {
  // A corner of a box: vertex 0 is shared by one triangle of the xy face (angle 90°) and two
  // triangles of the xz face (45° each). Angle weighting gives equal weight to both faces,
  // (0,0,1)·π/2 + (0,1,0)·π/2 → (0,1,1)/√2; area weighting (0.5 vs 1.0) would not.
  TempDir dir;
  dir.write("c.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 1\nv 0 0 1\n"
            "f 1 2 3\n"        // xy face, normal +z, 90° at vertex 1
            "f 1 5 4\nf 1 4 2\n");  // xz face, normal +y, 45° + 45° at vertex 1
  const Mesh m = loadText(dir, sceneXml("<shape type=\"obj\"><string name=\"filename\" value=\"c.obj\"/></shape>")).meshes.at(0);
  ASSERT_EQ(m.normals.size(), m.positions.size());
  const Vec3 expected = glm::normalize(Vec3(0, 1, 1));
  EXPECT_NEAR(glm::dot(m.normals[0], expected), 1.0f, 1e-6f);
}

TEST(SceneShapes, ComputedNormalsWeldSeams) {
  // Two triangles sharing an edge but with different uvs at it: split vertices, one normal.
  TempDir dir;
  dir.write("s.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\n"
                     "f 1/1 2/2 3/3\nf 1/4 4/2 2/3\n");
  const Mesh m = loadText(dir, sceneXml("<shape type=\"obj\"><string name=\"filename\" value=\"s.obj\"/></shape>")).meshes.at(0);
  ASSERT_EQ(m.positions.size(), 6u);
  EXPECT_EQ(m.normals[0], m.normals[3]);  // both copies of vertex 1
}

TEST(SceneShapes, DegenerateAndNaNTrianglesAreDroppedAndCounted) {
  TempDir dir;
  dir.write("d.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv nan 0 0\n"
                     "f 1 2 3\nf 1 2 4\nf 1 1 3\nf 5 2 3\n");
  const Mesh m = loadText(dir, sceneXml("<shape type=\"obj\"><string name=\"filename\" value=\"d.obj\"/></shape>")).meshes.at(0);
  EXPECT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.degenerateSkipped, 3u);
  for (const Vec3& n : m.normals) EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
}

TEST(SceneShapes, MeshWithOnlyDegenerateTrianglesIsAnError) {
  TempDir dir;
  dir.write("z.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  expectError([&] { loadText(dir, sceneXml("<shape type=\"obj\"><string name=\"filename\" value=\"z.obj\"/></shape>")); },
              {"no valid triangles", "1 degenerate"});
}

TEST(SceneShapes, MeshFileErrorsCarryBothLocations) {
  TempDir dir;
  dir.write("bad.obj", "v 0 0 0\nf 1 2 3\n");
  expectError([&] { loadText(dir, sceneXml("\n<shape type=\"obj\"><string name=\"filename\" value=\"bad.obj\"/></shape>")); },
              {"scene.xml:4:", "<shape type=\"obj\">", "bad.obj:2:", "out of range"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"ply\"><string name=\"filename\" value=\"none.ply\"/></shape>")); },
              {"<shape type=\"ply\">", "cannot open mesh file", "none.ply"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"obj\"/>")); }, {"missing parameter 'filename'"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"rectangle\"><boolean name=\"face_normals\" value=\"true\"/></shape>")); },
              {"unsupported parameter 'face_normals'"});
}

TEST(SceneShapes, PlyThroughTheXmlWithTransform) {
  TempDir dir;
  dir.write("t.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                     "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const Mesh m = loadText(dir, sceneXml("<shape type=\"ply\" id=\"tri\"><string name=\"filename\" value=\"t.ply\"/>"
                                        "<transform name=\"to_world\"><translate z=\"2\"/></transform></shape>")).meshes.at(0);
  EXPECT_EQ(m.positions[1], Vec3(1, 0, 2));
  EXPECT_EQ(m.normals.size(), 3u);
  EXPECT_EQ(m.name.rfind("tri (", 0), 0u);
  EXPECT_NE(m.name.find("scene.xml:3"), std::string::npos);
}

TEST(SceneShapes, ShapeWithoutBsdfGetsDiffuseHalf) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("<shape type=\"cube\"/><shape type=\"sphere\"/>"));
  ASSERT_EQ(s.bsdfs.size(), 1u);
  EXPECT_EQ(s.meshes[0].bsdf, 0);
  EXPECT_EQ(s.spheres[0].bsdf, 0);
  EXPECT_TRUE(s.bsdfs[0]->isDiffuseOnly());
  // Lambertian with reflectance 0.5: f·cos = 0.5/π · cos θi.
  const Color f = s.bsdfs[0]->eval(Vec3(0, 0, 1), Vec3(0, 0, 1));
  EXPECT_NEAR(f.g, 0.5f * kInvPi, 1e-6f);
}

// Mitsuba 3 (src/render/shape.cpp): the default diffuse of a shape that carries an area emitter has
// reflectance 0, so the emitter's radiance is all it sends; a shape beside it keeps the 0.5 one.
TEST(SceneShapes, EmitterShapeWithoutBsdfIsBlack) {
  TempDir dir;
  const Scene s = loadText(dir, sceneXml("<shape type=\"sphere\"><emitter type=\"area\"><rgb name=\"radiance\" "
                                         "value=\"1\"/></emitter></shape><shape type=\"cube\"/>"));
  ASSERT_EQ(s.bsdfs.size(), 2u);
  const Color emitterF = s.bsdfs.at(s.spheres.at(0).bsdf)->eval(Vec3(0, 0, 1), Vec3(0, 0, 1));
  EXPECT_EQ(emitterF.r, 0.0f);
  EXPECT_EQ(emitterF.g, 0.0f);
  EXPECT_EQ(emitterF.b, 0.0f);
  const Color plainF = s.bsdfs.at(s.meshes.at(0).bsdf)->eval(Vec3(0, 0, 1), Vec3(0, 0, 1));
  EXPECT_NEAR(plainF.g, 0.5f * kInvPi, 1e-6f);
}

}  // namespace
}  // namespace rc::test
