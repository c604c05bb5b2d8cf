// Every scene shipped in scenes/ (and scenes/stress/) loads without error or warning.
#include <filesystem>

#include "scene_test_util.h"

namespace rc::test {
namespace {

TEST(ShippedScenes, EveryXmlLoads) {
  const std::filesystem::path root = std::filesystem::path(RC_SOURCE_DIR) / "scenes";
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root))
    if (entry.is_regular_file() && entry.path().extension() == ".xml") files.push_back(entry.path().string());
  ASSERT_GE(files.size(), 6u) << "scenes/ should ship the scenes README lists";
  for (const std::string& f : files) {
    SCOPED_TRACE(f);
    std::vector<std::string> warnings;
    Scene s;
    ASSERT_NO_THROW(s = loadScene(f, {}, &warnings));
    EXPECT_TRUE(warnings.empty());
    EXPECT_FALSE(s.meshes.empty() && s.spheres.empty());
    EXPECT_FALSE(s.emitters.empty());
    for (const Mesh& m : s.meshes) EXPECT_EQ(m.degenerateSkipped, 0u) << m.name;
  }
}

}  // namespace
}  // namespace rc::test
