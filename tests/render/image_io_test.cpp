// Image files: EXR exact round trip with AOVs (and the same values through OpenImageIO), PNG sRGB
// encoding, HDR, and atomic writes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "core/rng.h"
#include "image/image_file.h"
#include "image/oiio_module.h"
#include "render/image_io.h"

namespace rc {
namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("rc_render_io_" + std::to_string(getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
  size_t entries() const { return static_cast<size_t>(std::distance(fs::directory_iterator(path), fs::directory_iterator())); }
};

Image randomImage(int w, int h, float scale, uint64_t seed) {
  Image img;
  img.width = w;
  img.height = h;
  Rng rng(seed);
  for (int i = 0; i < w * h; ++i) img.pixels.push_back(Color(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) * scale);
  return img;
}

TEST(ImageIo, ExrRoundTripIsExactWithAovs) {
  TempDir dir;
  Image img = randomImage(17, 9, 100.0f, 1);
  img.pixels[3] = Color(1e-30f, 65504.0f * 16.0f, 0.0f);  // beyond half range: must be float32
  img.aovs["records"] = randomImage(17, 9, 5.0f, 2).pixels;
  img.aovs["radius"] = randomImage(17, 9, 0.01f, 3).pixels;
  writeImage(img, dir.file("a.exr"));
  const Image back = readImage(dir.file("a.exr"));
  ASSERT_EQ(back.width, 17);
  ASSERT_EQ(back.height, 9);
  for (size_t i = 0; i < img.pixels.size(); ++i) EXPECT_EQ(back.pixels[i], img.pixels[i]) << i;
  ASSERT_EQ(back.aovs.size(), 2u);
  for (const auto& [name, layer] : img.aovs)
    for (size_t i = 0; i < layer.size(); ++i) EXPECT_EQ(back.aovs.at(name)[i], layer[i]) << name << i;
  EXPECT_EQ(dir.entries(), 1u);  // no temporary left behind
}

// Our EXR writer is OpenEXR itself; OpenImageIO (what other tools use, and what rcache read its
// EXRs with before) reads the same channels and values back.
TEST(ImageIo, ExrWrittenWithOpenExrReadsTheSameThroughOpenImageIo) {
  TempDir dir;
  Image img = randomImage(13, 7, 10.0f, 9);
  img.aovs["technique"] = randomImage(13, 7, 1.0f, 10).pixels;
  writeImage(img, dir.file("x.exr"));
  ImageChannels viaOiio;
  ASSERT_EQ(oiioModule().read(dir.file("x.exr"), viaOiio), "");
  ASSERT_EQ(viaOiio.width, 13);
  ASSERT_EQ(viaOiio.height, 7);
  ASSERT_EQ(viaOiio.channels(), 6u);
  int rgb[3];
  rgbChannelIndices(viaOiio, rgb);
  const int aov = channelIndex(viaOiio, "technique.G");
  ASSERT_GE(aov, 0);
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(viaOiio.data[i * 6 + rgb[c]], img.pixels[i][c]) << i;
    EXPECT_EQ(viaOiio.data[i * 6 + aov], img.aovs["technique"][i].g) << i;
  }
  // And the other way: an EXR that OpenImageIO wrote reads here.
  ImageChannels other;
  other.width = 3;
  other.height = 2;
  other.names = {"R", "G", "B"};
  other.data = {0.5f, 1, 2, 4, 8, 16, 0.25f, 0.125f, 3, 5, 6, 7, 9, 10, 11, 12, 13, 14};
  ASSERT_EQ(oiioModule().write(dir.file("oiio.exr"), dir.file("oiio.exr"), other), "");
  const Image back = readImage(dir.file("oiio.exr"));
  ASSERT_EQ(back.width, 3);
  for (size_t i = 0; i < 6; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(back.pixels[i][c], other.data[3 * i + c]) << i;
}

TEST(ImageIo, PngIsSrgbEncodedAndClamped) {
  TempDir dir;
  Image img = randomImage(8, 8, 1.0f, 4);
  img.pixels[0] = Color(2.0f, -1.0f, 0.5f);
  writeImage(img, dir.file("a.png"));
  const Image back = readImage(dir.file("a.png"));
  // Round trip through 8-bit sRGB: the encoded value is within half a code of the exact encoding.
  for (size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const float expected = std::min(1.0f, std::max(0.0f, linearToSrgb(img.pixels[i][c])));
      EXPECT_NEAR(linearToSrgb(back.pixels[i][c]), expected, 0.5f / 255.0f + 1e-5f) << i;
    }
  EXPECT_NEAR(back.pixels[0].r, 1.0f, 1e-6f);
  EXPECT_NEAR(back.pixels[0].g, 0.0f, 1e-6f);
  // 0.5 linear is code 188 in sRGB, not 128.
  EXPECT_NEAR(linearToSrgb(back.pixels[0].b) * 255.0f, 188.0f, 0.51f);
}

TEST(ImageIo, HdrRoundTripWithinRgbePrecision) {
  TempDir dir;
  const Image img = randomImage(6, 5, 50.0f, 5);
  writeImage(img, dir.file("a.hdr"));
  const Image back = readImage(dir.file("a.hdr"));
  // RGBE keeps 8 mantissa bits relative to the largest channel: error ≤ max channel / 128.
  for (size_t i = 0; i < img.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(back.pixels[i][c], img.pixels[i][c], maxComponent(img.pixels[i]) / 128.0f);
}

TEST(ImageIo, UnknownExtensionNamesThePath) {
  TempDir dir;
  const std::string path = dir.file("out.tiff2");
  try {
    writeImage(randomImage(2, 2, 1, 6), path);
    FAIL() << "expected rc::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_EQ(dir.entries(), 0u);
}

TEST(ImageIo, FailureLeavesNoPartialFile) {
  TempDir dir;
  // Missing directory: cannot be opened.
  const std::string missing = dir.file("nope/out.exr");
  try {
    writeImage(randomImage(4, 4, 1, 7), missing);
    FAIL() << "expected rc::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  // Target is a directory: the image is written to the temporary, the rename fails, and the
  // temporary is removed.
  fs::create_directories(dir.path / "taken.exr" / "x");
  EXPECT_THROW(writeImage(randomImage(4, 4, 1, 8), dir.file("taken.exr")), Error);
  EXPECT_EQ(dir.entries(), 1u);  // only the directory we made
  // An existing good file is not touched by a failed overwrite.
  writeImage(randomImage(4, 4, 1, 9), dir.file("good.exr"));
  Image bad = randomImage(4, 4, 1, 10);
  bad.pixels.resize(3);  // inconsistent size
  EXPECT_THROW(writeImage(bad, dir.file("good.exr")), Error);
  EXPECT_EQ(readImage(dir.file("good.exr")).pixels, randomImage(4, 4, 1, 9).pixels);
  EXPECT_EQ(dir.entries(), 2u);
}

TEST(ImageIo, ReadMissingFileNamesThePath) {
  try {
    readImage("/nonexistent/dir/img.exr");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/img.exr"), std::string::npos);
  }
}

}  // namespace
}  // namespace rc
