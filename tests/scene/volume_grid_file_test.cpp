// Mitsuba's `.vol` grid files, written here byte by byte after src/render/volumegrid.cpp, and
// malformed ones: each must fail with a message naming the file and the fault.
#include <cstring>
#include <fstream>

#include "common/vol_file_bytes.h"
#include "core/error.h"
#include "scene/volume_grid_file.h"
#include "scene_test_util.h"

namespace rc::test {
namespace {

// Each test process writes into its own folder: ctest runs the tests of this file in parallel.
std::string writeFile(const std::string& name, const std::string& bytes) {
  static TempDir dir;
  return dir.write(name, bytes);
}

std::string errorOf(const std::string& bytes) {
  const std::string path = writeFile("bad.vol", bytes);
  try {
    readVolumeGrid(path);
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

TEST(VolumeGridFile, ReadsValuesXFastestWithChannelsTogether) {
  VolBytes b = volHeader(2, 3, 4, 2);
  for (int i = 0; i < 2 * 3 * 4 * 2; ++i) b.f32(static_cast<float>(i));
  b.s += "trailing";
  const VolumeGrid g = readVolumeGrid(writeFile("ok.vol", b.s));
  EXPECT_EQ(g.size[0], 2u);
  EXPECT_EQ(g.size[1], 3u);
  EXPECT_EQ(g.size[2], 4u);
  EXPECT_EQ(g.channels, 2u);
  EXPECT_EQ(g.boundsMin[2], -3.f);
  EXPECT_EQ(g.boundsMax[0], 1.f);
  // Voxel (x=1, y=2, z=3), channel 1: ((3·3 + 2)·2 + 1)·2 + 1 = 47.
  EXPECT_EQ(g.at(1, 2, 3, 1), 47.f);
  EXPECT_EQ(g.at(0, 0, 0, 0), 0.f);
}

TEST(VolumeGridFile, RejectsMalformedFiles) {
  EXPECT_NE(errorOf("VOL").find("48-byte header"), std::string::npos);
  VolBytes magic = volHeader(1, 1, 1, 1);
  magic.s[0] = 'X';
  EXPECT_NE(errorOf(magic.s).find("\"VOL\""), std::string::npos);
  VolBytes version = volHeader(1, 1, 1, 1);
  version.s[3] = 2;
  EXPECT_NE(errorOf(version.s).find("version 2"), std::string::npos);
  VolBytes encoding;
  encoding.i32(2);
  for (int i = 0; i < 10; ++i) encoding.i32(1);
  EXPECT_NE(errorOf(encoding.s).find("encoding 2"), std::string::npos);
  EXPECT_NE(errorOf(volHeader(0, 1, 1, 1).s).find("resolution along x is 0"), std::string::npos);
  EXPECT_NE(errorOf(volHeader(1, 1, 1, -3).s).find("channel count -3"), std::string::npos);
}

TEST(VolumeGridFile, HeaderPromisingMoreThanTheFileHoldsFailsBeforeAllocating) {
  // 2^31-1 cubed overflows 64 bits; the reader must notice before multiplying or allocating.
  EXPECT_NE(errorOf(volHeader(0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff).s).find("truncated"), std::string::npos);
  VolBytes shortData = volHeader(2, 2, 2, 1);
  for (int i = 0; i < 7; ++i) shortData.f32(1.f);
  EXPECT_NE(errorOf(shortData.s).find("truncated"), std::string::npos);
  VolBytes nan = volHeader(1, 1, 1, 1);
  nan.f32(std::nanf(""));
  EXPECT_NE(errorOf(nan.s).find("value 0 is not finite"), std::string::npos);
  EXPECT_NE(errorOf("").find("48-byte header"), std::string::npos);
}

}  // namespace
}  // namespace rc::test
