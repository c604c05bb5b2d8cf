// The `serialized` shape: files written here byte by byte after Mitsuba's format description
// (src/shapes/serialized.cpp), versions 3 and 4, several shapes per file, and malformed files.
#include <zlib.h>

#include <cstring>

#include "scene/serialized_loader.h"
#include "scene_test_util.h"

namespace rc::test {
namespace {

struct Bytes {
  std::string s;
  template <class T>
  void put(T v) {
    for (size_t i = 0; i < sizeof(T); ++i) s.push_back(static_cast<char>((static_cast<uint64_t>(v) >> (8 * i)) & 0xff));
  }
  void putFloat(float f) { uint32_t b; std::memcpy(&b, &f, 4); put(b); }
  void putDouble(double d) { uint64_t b; std::memcpy(&b, &d, 8); put(b); }
};

std::string deflate(const std::string& in) {
  uLongf size = compressBound(in.size());
  std::string out(size, '\0');
  EXPECT_EQ(compress(reinterpret_cast<Bytef*>(&out[0]), &size, reinterpret_cast<const Bytef*>(in.data()), in.size()), Z_OK);
  out.resize(size);
  return out;
}

// One shape: header + zlib(flags, [name], V, F, positions, [normals], [uvs], indices).
std::string shape(uint16_t version, bool extras, bool doubles) {
  Bytes body;
  body.put<uint32_t>((extras ? 0x0001 | 0x0002 | 0x0008 : 0) | (doubles ? 0x2000 : 0x1000));
  if (version == 4) body.s += std::string("tri") + '\0';
  body.put<uint64_t>(3);
  body.put<uint64_t>(1);
  auto real = [&](double v) { doubles ? body.putDouble(v) : body.putFloat(static_cast<float>(v)); };
  for (double v : {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 2.0, 0.0}) real(v);
  if (extras) {
    for (int i = 0; i < 3; ++i) for (double v : {0.0, 0.0, 1.0}) real(v);       // normals
    for (double v : {0.0, 0.0, 1.0, 0.0, 0.0, 0.5}) real(v);                    // uvs
    for (int i = 0; i < 9; ++i) real(0.25);                                     // colours (read past)
  }
  body.put<uint32_t>(0);
  body.put<uint32_t>(1);
  body.put<uint32_t>(2);
  Bytes head;
  head.put<uint16_t>(0x041C);
  head.put<uint16_t>(version);
  return head.s + deflate(body.s);
}

// Shapes concatenated, then the offset table and the count.
std::string file(uint16_t version, const std::vector<std::string>& shapes) {
  Bytes out, table;
  for (const std::string& s : shapes) {
    version == 4 ? table.put<uint64_t>(out.s.size()) : table.put<uint32_t>(static_cast<uint32_t>(out.s.size()));
    out.s += s;
  }
  table.put<uint32_t>(static_cast<uint32_t>(shapes.size()));
  return out.s + table.s;
}

TEST(SerializedShape, ReadsEveryShapeOfVersions3And4) {
  TempDir dir;
  for (uint16_t version : {uint16_t(3), uint16_t(4)}) {
    const std::string path = dir.write("m.serialized", file(version, {shape(version, false, false), shape(version, true, true)}));
    const MeshData a = loadSerialized(path, 0);
    ASSERT_EQ(a.positions.size(), 3u);
    EXPECT_EQ(a.positions[2], Vec3(0, 2, 0));
    EXPECT_TRUE(a.normals.empty());
    EXPECT_TRUE(a.uvs.empty());
    ASSERT_EQ(a.triangles.size(), 1u);
    EXPECT_EQ(a.triangles[0], glm::uvec3(0, 1, 2));
    const MeshData b = loadSerialized(path, 1);
    ASSERT_EQ(b.normals.size(), 3u);
    EXPECT_EQ(b.normals[1], Vec3(0, 0, 1));
    ASSERT_EQ(b.uvs.size(), 3u);
    EXPECT_EQ(b.uvs[2], Vec2(0, 0.5f));
    EXPECT_EQ(b.positions[1], Vec3(1, 0, 0));
  }
}

TEST(SerializedShape, LoadsAsAShapeWithItsTransform) {
  TempDir dir;
  dir.write("m.serialized", file(4, {shape(4, false, false), shape(4, true, false)}));
  const Scene s = loadText(dir, sceneXml("<shape type=\"serialized\"><string name=\"filename\" value=\"m.serialized\"/>"
                                         "<integer name=\"shape_index\" value=\"1\"/><boolean name=\"face_normals\" value=\"true\"/>"
                                         "<transform name=\"to_world\"><translate z=\"5\"/></transform></shape>"));
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].positions[1], Vec3(1, 0, 5));
  EXPECT_EQ(s.meshes[0].uvs.size(), 3u);
}

TEST(SerializedShape, MalformedFilesAreErrors) {
  TempDir dir;
  const std::string good = file(4, {shape(4, true, false)});
  auto bad = [&](const std::string& bytes, int index, std::initializer_list<std::string> parts) {
    const std::string path = dir.write("bad.serialized", bytes);
    expectError([&] { loadSerialized(path, index); }, parts);
  };
  bad("xy", 0, {"bad.serialized", "bad magic"});
  std::string v5 = good;
  v5[2] = 5;
  bad(v5, 0, {"version 5"});
  bad(good, 1, {"shape_index 1 is out of range", "1 shapes"});
  bad(good.substr(0, good.size() / 2), 0, {"bad.serialized"});
  std::string corrupt = good;
  for (size_t i = 8; i < 20; ++i) corrupt[i] = static_cast<char>(0x5a);
  bad(corrupt, 0, {"bad.serialized"});
  // A header claiming 2^40 vertices in a tiny file fails before allocating for them.
  Bytes body;
  body.put<uint32_t>(0x1000);
  body.s += '\0';
  body.put<uint64_t>(1ull << 40);
  body.put<uint64_t>(1);
  Bytes head;
  head.put<uint16_t>(0x041C);
  head.put<uint16_t>(4);
  bad(head.s + deflate(body.s), 0, {"exceed what the file can hold"});
  // An index out of range.
  Bytes tri;
  tri.put<uint32_t>(0x1000);
  tri.s += '\0';
  tri.put<uint64_t>(1);
  tri.put<uint64_t>(1);
  for (int i = 0; i < 3; ++i) tri.putFloat(0.0f);
  for (uint32_t i : {0u, 0u, 7u}) tri.put<uint32_t>(i);
  bad(head.s + deflate(tri.s), 0, {"vertex index out of range"});
  expectError([&] { loadText(dir, sceneXml("<shape type=\"serialized\"><string name=\"filename\" value=\"bad.serialized\"/>"
                                           "\n<integer name=\"shape_index\" value=\"-1\"/></shape>")); },
              {"scene.xml:4:", "'shape_index' must be non-negative"});
}

}  // namespace
}  // namespace rc::test
