// Mesh attributes: a PLY's extra vertex/face properties grouped and named as Mitsuba's PLY loader
// does, kept aligned with the triangles through fan triangulation and degenerate-triangle removal,
// and the mesh_attribute texture's value at a surface point against hand-computed blends.
#include "scene_test_util.h"
#include "texture/texture.h"

namespace rc::test {
namespace {

const MeshAttribute* attributeNamed(const Mesh& m, const std::string& name) {
  for (const MeshAttribute& a : m.attributes)
    if (a.name == name) return &a;
  return nullptr;
}

std::string plyHeader(int vertices, const std::string& vertexProps, int faces, const std::string& faceProps) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\n" + vertexProps + "element face " +
         std::to_string(faces) + "\nproperty list uchar int vertex_indices\n" + faceProps + "end_header\n";
}

TEST(MeshAttributes, PlyPropertiesAreGroupedAsMitsubaDoes) {
  TempDir dir;
  // Vertex: red green blue → vertex_color; foo_x foo_y foo_z → vertex_foo; n_r n_g n_b →
  // vertex_n_color; w_0 → vertex_w; two_0 two_1 (2 channels) and plain are dropped.
  const std::string vprops =
      "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty float foo_x\nproperty float foo_y\n"
      "property float foo_z\nproperty float n_r\nproperty float n_g\nproperty float n_b\nproperty float w_0\n"
      "property float two_0\nproperty float two_1\nproperty float plain\n";
  // Face: q_1 q_2 q_3 → face_q; a quad and a degenerate triangle.
  const std::string fprops = "property float q_1\nproperty float q_2\nproperty float q_3\n";
  std::string body;
  for (int i = 0; i < 5; ++i) {
    const float x = i == 1 || i == 2 ? 1.0f : 0.0f, y = i >= 2 && i < 4 ? 1.0f : 0.0f;
    body += std::to_string(x) + " " + std::to_string(y) + " 0 " + std::to_string(10 * i) + " 1 2 " +
            std::to_string(i) + " 0.5 0.25 7 8 9 " + std::to_string(0.1f * i) + " 1 1 3\n";
  }
  body += "4 0 1 2 3 0.1 0.2 0.3\n3 0 1 4 0.4 0.5 0.6\n3 0 2 3 0.7 0.8 0.9\n";  // vertex 4 = vertex 0: degenerate
  dir.write("m.ply", plyHeader(5, vprops, 3, fprops) + body);
  const Scene s = loadText(dir, sceneXml("<shape type=\"ply\"><string name=\"filename\" value=\"m.ply\"/></shape>"));
  const Mesh& m = s.meshes.at(0);
  std::vector<std::string> names;
  for (const MeshAttribute& a : m.attributes) names.push_back(a.name);
  EXPECT_EQ(names, (std::vector<std::string>{"vertex_color", "vertex_foo", "vertex_n_color", "vertex_w", "face_q"}));
  const MeshAttribute* color = attributeNamed(m, "vertex_color");
  ASSERT_TRUE(color);
  EXPECT_EQ(color->channels, 3);
  EXPECT_FALSE(color->perFace);
  ASSERT_EQ(color->values.size(), 15u);
  EXPECT_EQ(color->values[6], 20.0f);  // vertex 2's red, as stored (Mitsuba does not rescale integers)
  EXPECT_EQ(attributeNamed(m, "vertex_w")->channels, 1);
  EXPECT_FLOAT_EQ(attributeNamed(m, "vertex_w")->values[3], 0.3f);
  // The quad's two triangles share its value; the degenerate triangle and its value are gone.
  ASSERT_EQ(m.triangles.size(), 3u);
  const MeshAttribute* q = attributeNamed(m, "face_q");
  ASSERT_TRUE(q);
  EXPECT_TRUE(q->perFace);
  EXPECT_EQ(q->values, (std::vector<float>{0.1f, 0.2f, 0.3f, 0.1f, 0.2f, 0.3f, 0.7f, 0.8f, 0.9f}));
}

TEST(MeshAttributes, TextureBlendsVertexValuesAndReadsFaceValues) {
  MeshAttributes attrs(3);
  attrs[0] = {"vertex_color", false, 3, {0.1f, 0.2f, 0.3f, 0.5f, 0.2f, 0.1f, 0.9f, 0.6f, 0.5f, 0.5f, 0.6f, 0.7f}};
  attrs[1] = {"face_weight", true, 1, {0.25f, 0.75f}};
  attrs[2] = {"vertex_uv", false, 2, {0, 0, 1, 0, 1, 1, 0, 1}};
  TexturePoint p(Vec2(0.3f, 0.9f));
  p.attributes = &attrs;
  p.vertices = glm::uvec3(0, 2, 3);
  p.face = 1;
  p.bary = Vec2(0.2f, 0.5f);  // weights 0.3, 0.2, 0.5 of vertices 0, 2, 3
  const Color vertex = makeMeshAttributeTexture("vertex_color", 2.0f)->eval(p);
  const Color expected = 2.0f * (0.3f * Color(0.1f, 0.2f, 0.3f) + 0.2f * Color(0.9f, 0.6f, 0.5f) + 0.5f * Color(0.5f, 0.6f, 0.7f));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(vertex[k], expected[k], 1e-6f);
  EXPECT_EQ(makeMeshAttributeTexture("face_weight", 1.0f)->eval(p), Color(0.75f));  // one value: grey
  EXPECT_EQ(makeMeshAttributeTexture("vertex_uv", 1.0f)->eval(p), Color(0.0f));    // two values: black (Mitsuba)
  EXPECT_EQ(makeMeshAttributeTexture("vertex_none", 1.0f)->eval(p), Color(0.0f));
  EXPECT_EQ(makeMeshAttributeTexture("vertex_color", 1.0f)->eval(TexturePoint(Vec2(0.5f))), Color(0.0f));
  EXPECT_EQ(makeMeshAttributeTexture("vertex_color", 1.0f)->meshAttribute(), "vertex_color");
}

TEST(MeshAttributes, LoaderChecksWhereTheTextureIsUsed) {
  TempDir dir;
  dir.write("m.ply", plyHeader(3, "property float w_0\n", 1, "") + "0 0 0 1\n1 0 0 2\n0 1 0 3\n3 0 1 2\n");
  const auto load = [&](const std::string& body) { return [&dir, body] { loadText(dir, sceneXml(body)); }; };
  const std::string reads = "<bsdf type=\"diffuse\"><texture type=\"mesh_attribute\" name=\"reflectance\">"
                            "<string name=\"name\" value=\"vertex_color\"/></texture></bsdf>";
  expectError(load("<shape type=\"ply\"><string name=\"filename\" value=\"m.ply\"/>" + reads + "</shape>"),
              {"scene.xml:3:", "'vertex_color'", "it has vertex_w"});
  expectError(load("<shape type=\"sphere\">" + reads + "</shape>"), {"scene.xml:3:", "a sphere has no attributes"});
  // Through a twosided wrapper and a <ref>, the attribute is still required.
  expectError(load("<bsdf type=\"twosided\" id=\"m\">" + reads + "</bsdf><shape type=\"rectangle\"><ref id=\"m\"/></shape>"),
              {"scene.xml:3:", "<shape type=\"rectangle\">", "'vertex_color'", "it has none"});
  expectError(load("<bsdf type=\"diffuse\"><texture type=\"mesh_attribute\" name=\"reflectance\">"
                   "<string name=\"name\" value=\"color\"/></texture></bsdf>"),
              {"scene.xml:3:", "'vertex_' or 'face_'"});
  expectError(load("<bsdf type=\"roughconductor\"><texture type=\"mesh_attribute\" name=\"alpha\">"
                   "<string name=\"name\" value=\"vertex_w\"/></texture></bsdf>"),
              {"scene.xml:3:", "mesh_attribute texture on parameter 'alpha'"});
  expectError(load("<emitter type=\"spot\"><texture type=\"mesh_attribute\" name=\"texture\">"
                   "<string name=\"name\" value=\"vertex_w\"/></texture></emitter>"),
              {"scene.xml:3:", "an emitter's image has none"});
  // The attribute present: loads.
  const Scene s = loadText(dir, sceneXml("<shape type=\"ply\"><string name=\"filename\" value=\"m.ply\"/>"
                                         "<bsdf type=\"diffuse\"><texture type=\"mesh_attribute\" name=\"reflectance\">"
                                         "<string name=\"name\" value=\"vertex_w\"/></texture></bsdf></shape>"));
  EXPECT_TRUE(s.bsdfs.at(0)->tinted());
}

}  // namespace
}  // namespace rc::test
