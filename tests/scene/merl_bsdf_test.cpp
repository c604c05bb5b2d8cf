// <bsdf type="merl">: the data file is found relative to the scene file, and a bad one is reported
// at the element's line with the file's name.
#include "bsdf/merl_data.h"
#include "scene_test_util.h"

namespace rc::test {
namespace {

MerlData tinyTable() {
  MerlData d;
  d.thetaHalfRes = 4;
  d.thetaDiffRes = 3;
  d.phiDiffRes = 6;
  d.values.assign(3 * d.nodeCount(), 0.1f);
  return d;
}

const char* kMerlShape =
    "<shape type=\"rectangle\"><bsdf type=\"merl\" id=\"m\"><string name=\"filename\" value=\"data/m.binary\"/></bsdf></shape>";

TEST(SceneMerl, FilenameIsRelativeToTheSceneFile) {
  TempDir dir;
  std::filesystem::create_directories(dir.path("data"));
  writeMerlFile(dir.path("data/m.binary"), tinyTable());
  const Scene s = loadText(dir, sceneXml(kMerlShape));
  ASSERT_EQ(s.bsdfs.size(), 1u);
  EXPECT_EQ(s.bsdfs[0]->typeName(), "merl");
  EXPECT_EQ(s.bsdfs[0]->id, "m");
}

TEST(SceneMerl, BadFileIsReportedAtTheElementWithItsName) {
  TempDir dir;
  std::filesystem::create_directories(dir.path("data"));
  dir.write("data/m.binary", "short");
  expectError([&] { loadText(dir, sceneXml(kMerlShape)); },
              {"scene.xml:3", "<bsdf type=\"merl\"", "data/m.binary", "truncated header"});
  expectError([&] { loadText(dir, sceneXml("<bsdf type=\"merl\" id=\"x\"/>")); }, {"scene.xml:3", "filename"});
}

}  // namespace
}  // namespace rc::test
