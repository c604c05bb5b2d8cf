// OBJ and PLY readers on files written here: polygon forms, index forms, binary PLY, broken files.
#include <cstring>

#include "scene/obj_loader.h"
#include "scene/ply_loader.h"
#include "scene_test_util.h"

namespace rc::test {
namespace {

TEST(ObjLoader, QuadIsFanTriangulatedAndVerticesShared) {
  TempDir dir;
  const MeshData m = loadObj(dir.write("q.obj", "# quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"), true);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
  EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 3));
  EXPECT_TRUE(m.normals.empty());
  EXPECT_TRUE(m.uvs.empty());
}

TEST(ObjLoader, PentagonGivesThreeTriangles) {
  TempDir dir;
  const MeshData m = loadObj(dir.write("p.obj", "v 0 0 0\nv 1 0 0\nv 1.5 1 0\nv 0.5 2 0\nv -0.5 1 0\nf 1 2 3 4 5\n"), true);
  EXPECT_EQ(m.triangles.size(), 3u);
}

TEST(ObjLoader, AllIndexFormsAndNegativeIndices) {
  TempDir dir;
  const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 0.25\nvn 0 0 1\n";
  const MeshData a = loadObj(dir.write("a.obj", head + "f 1/1/1 2/2/1 3/3/1\n"), false);
  ASSERT_EQ(a.uvs.size(), 3u);
  ASSERT_EQ(a.normals.size(), 3u);
  EXPECT_EQ(a.uvs[2], Vec2(0, 0.25f));
  const MeshData flipped = loadObj(dir.write("f.obj", head + "f 1/1/1 2/2/1 3/3/1\n"), true);
  EXPECT_EQ(flipped.uvs[2], Vec2(0, 0.75f));  // Mitsuba's flip_tex_coords: v → 1 − v
  const MeshData b = loadObj(dir.write("b.obj", head + "f 1//1 2//1 3//1\n"), false);
  EXPECT_EQ(b.normals.size(), 3u);
  EXPECT_TRUE(b.uvs.empty());
  const MeshData c = loadObj(dir.write("c.obj", head + "f 1/1 2/2 3/3\n"), false);
  EXPECT_TRUE(c.normals.empty());
  EXPECT_EQ(c.uvs.size(), 3u);
  const MeshData d = loadObj(dir.write("d.obj", head + "f -3/-3/-1 -2/-2/-1 -1/-1/-1\n"), false);
  EXPECT_EQ(d.positions, a.positions);
  EXPECT_EQ(d.uvs, a.uvs);
}

TEST(ObjLoader, RelativeIndicesReferToVerticesSoFar) {
  TempDir dir;
  const MeshData m = loadObj(dir.write("r.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nv 6 5 5\nv 5 6 5\nf -3 -2 -1\n"), true);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.positions[m.triangles[1].x], Vec3(5, 5, 5));
}

TEST(ObjLoader, IgnoresGroupsMaterialsAndComments) {
  TempDir dir;
  const MeshData m = loadObj(dir.write("g.obj", "mtllib x.mtl\no thing\ng part\ns 1\nusemtl red\nv 0 0 0 # c\nv 1 0 0\nv 0 1 0\r\nf 1 2 3\n"), true);
  EXPECT_EQ(m.triangles.size(), 1u);
}

TEST(ObjLoader, MixedNormalPresenceDropsNormals) {
  TempDir dir;
  const MeshData m = loadObj(dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 2 4 3\n"), true);
  EXPECT_TRUE(m.normals.empty());
  EXPECT_EQ(m.triangles.size(), 2u);
}

TEST(ObjLoader, ErrorsNameFileAndLine) {
  TempDir dir;
  const std::string p = dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 9\n");
  expectError([&] { loadObj(p, true); }, {"bad.obj:5:", "vertex index 9 out of range"});
  expectError([&] { loadObj(dir.write("z.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), true); }, {"z.obj:4:", "index 0"});
  expectError([&] { loadObj(dir.write("n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n"), true); }, {"n.obj:4:", "out of range"});
  expectError([&] { loadObj(dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2 2 3\n"), true); }, {"texture coordinate index 2"});
  expectError([&] { loadObj(dir.write("s.obj", "v 0 0\n"), true); }, {"s.obj:1:", "needs 3 values"});
  expectError([&] { loadObj(dir.write("x.obj", "v 0 zero 0\n"), true); }, {"x.obj:1:", "'zero' is not a number"});
  expectError([&] { loadObj(dir.write("f.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"), true); }, {"f.obj:3:", "at least 3 vertices"});
  expectError([&] { loadObj(dir.path("missing.obj"), true); }, {"cannot open mesh file", "missing.obj"});
}

// --- PLY ---

const char* kPlyQuadAscii =
    "ply\nformat ascii 1.0\ncomment a unit quad\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\nproperty float u\nproperty float v\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n0 1 0 0 0 1 0 1\n4 0 1 2 3\n";

TEST(PlyLoader, AsciiQuadWithNormalsAndUvs) {
  TempDir dir;
  const MeshData m = loadPly(dir.write("q.ply", kPlyQuadAscii));
  ASSERT_EQ(m.positions.size(), 4u);
  ASSERT_EQ(m.normals.size(), 4u);
  ASSERT_EQ(m.uvs.size(), 4u);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.positions[2], Vec3(1, 1, 0));
  EXPECT_EQ(m.uvs[3], Vec2(0, 1));
  EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 3));
}

TEST(PlyLoader, AlternativeUvNamesAndVertexIndexAndExtraElements) {
  TempDir dir;
  const MeshData m = loadPly(dir.write("a.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
      "property uchar red\nproperty float s\nproperty float t\nelement face 1\nproperty list int uint vertex_index\n"
      "property int flags\nelement edge 1\nproperty int a\nproperty int b\nend_header\n"
      "0 0 0 255 0 0\n1 0 0 255 1 0\n0 1 0 255 0 1\n3 0 1 2 7\n0 1\n"));
  EXPECT_EQ(m.triangles.size(), 1u);
  ASSERT_EQ(m.uvs.size(), 3u);
  EXPECT_EQ(m.uvs[2], Vec2(0, 1));
  EXPECT_TRUE(m.normals.empty());
}

template <class T>
void put(std::string& s, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  s.append(b, sizeof(T));
}

std::string binaryPly(int faceCountType /*0: uchar, 1: int*/, bool truncate) {
  std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                  "property float z\nproperty double texture_u\nproperty double texture_v\n"
                  "element face 2\n";
  s += faceCountType == 0 ? "property list uchar int vertex_indices\n" : "property list int uint vertex_indices\n";
  s += "end_header\n";
  const float p[4][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  for (int i = 0; i < 4; ++i) {
    for (float c : p[i]) put(s, c);
    put(s, double(p[i][0] / 2));
    put(s, double(p[i][1] / 2));
  }
  const int faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (const auto& f : faces) {
    if (faceCountType == 0) put(s, uint8_t(3));
    else put(s, int32_t(3));
    for (int i : f) {
      if (faceCountType == 0) put(s, int32_t(i));
      else put(s, uint32_t(i));
    }
  }
  if (truncate) s.resize(s.size() - 5);
  return s;
}

TEST(PlyLoader, BinaryLittleEndianWithMixedTypes) {
  TempDir dir;
  for (int countType : {0, 1}) {
    const MeshData m = loadPly(dir.write("b.ply", binaryPly(countType, false)));
    ASSERT_EQ(m.positions.size(), 4u);
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.positions[2], Vec3(2, 2, 0));
    EXPECT_EQ(m.uvs[2], Vec2(1, 1));
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 3));
  }
}

TEST(PlyLoader, HeaderThatLiesIsAnError) {
  TempDir dir;
  expectError([&] { loadPly(dir.write("t.ply", binaryPly(0, true))); }, {"t.ply", "unexpected end of file", "element 'face'"});
  std::string ascii = kPlyQuadAscii;
  ascii.resize(ascii.find("4 0 1 2 3"));
  expectError([&] { loadPly(dir.write("a.ply", ascii)); }, {"a.ply", "unexpected end of file"});
}

TEST(PlyLoader, MalformedFilesAreErrors) {
  TempDir dir;
  expectError([&] { loadPly(dir.write("n.ply", "solid cube\n")); }, {"n.ply:1:", "not a PLY file"});
  expectError([&] { loadPly(dir.write("e.ply", "ply\nformat binary_big_endian 1.0\nend_header\n")); }, {"e.ply:2:", "binary_big_endian"});
  expectError([&] { loadPly(dir.write("h.ply", "ply\nformat ascii 1.0\nelement vertex 0\n")); }, {"no 'end_header'"});
  expectError([&] { loadPly(dir.write("p.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n")); },
              {"p.ply:4:", "unknown property type 'float128'"});
  std::string oob = kPlyQuadAscii;
  oob.replace(oob.find("4 0 1 2 3"), 9, "4 0 1 2 9");
  expectError([&] { loadPly(dir.write("o.ply", oob)); }, {"o.ply", "vertex index 9 out of range"});
  expectError([&] { loadPly(dir.write("f.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                               "property float z\nelement face 0\nproperty list uchar int foo\nend_header\n0 0 0\n")); },
              {"lacks a 'vertex_indices' list"});
  std::string infIndex = kPlyQuadAscii;
  infIndex.replace(infIndex.find("4 0 1 2 3"), 9, "4 0 1 2 inf");
  expectError([&] { loadPly(dir.write("i.ply", infIndex)); }, {"i.ply", "'inf' is not an integer"});
  std::string nanCount = kPlyQuadAscii;
  nanCount.replace(nanCount.find("4 0 1 2 3"), 9, "nan 0 1 2 3");
  expectError([&] { loadPly(dir.write("c.ply", nanCount)); }, {"c.ply", "'nan' is not an integer"});
  expectError([&] { loadPly(dir.path("missing.ply")); }, {"cannot open mesh file"});
}

}  // namespace
}  // namespace rc::test
