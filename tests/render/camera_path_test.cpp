// Camera paths (render/camera_path.h): the spline passes through every keyframe, moves smoothly
// between them, and malformed files are errors naming file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "render/camera_path.h"

namespace rc {
namespace {

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path, std::ios::trunc) << text;
  return path;
}

const char* kPath = R"({"keyframes": [
  {"origin": [0, 1, 4], "target": [0, 0.5, 0], "fov": 40},
  {"origin": [2, 1, 3], "target": [0, 0.5, 0], "fov": 45},
  {"origin": [3, 1.5, 0], "target": [0, 0.5, 0], "up": [0, 1, 0], "fov": 50}
]})";

TEST(CameraPath, PassesThroughKeyframes) {
  const auto keys = readCameraPath(writeFile("rc_path_ok.json", kPath));
  ASSERT_EQ(keys.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const CameraKey c = interpolateCameraPath(keys, k / 2.0f);
    EXPECT_NEAR(glm::length(c.origin - keys[k].origin), 0.0f, 1e-5f) << k;
    EXPECT_NEAR(c.fov, keys[k].fov, 1e-4f);
  }
  Camera base;
  const Camera first = cameraOfFrame(base, keys, 0, 5), last = cameraOfFrame(base, keys, 4, 5);
  EXPECT_NEAR(first.toWorld[3].z, 4.0f, 1e-5f);
  EXPECT_NEAR(last.toWorld[3].x, 3.0f, 1e-5f);
  EXPECT_FLOAT_EQ(last.fovDegrees, 50.0f);
}

// C¹: the velocity just before and just after an interior key agree (a piecewise-linear path
// would jump from one segment's direction to the other's).
TEST(CameraPath, VelocityIsContinuousAtKeys) {
  const auto keys = readCameraPath(writeFile("rc_path_c1.json", kPath));
  const float e = 1e-3f;
  const Vec3 before = (interpolateCameraPath(keys, 0.5f).origin - interpolateCameraPath(keys, 0.5f - e).origin) / e;
  const Vec3 after = (interpolateCameraPath(keys, 0.5f + e).origin - interpolateCameraPath(keys, 0.5f).origin) / e;
  EXPECT_LT(glm::length(before - after), 0.05f * glm::length(before));
}

TEST(CameraPath, BadFilesNameFileAndLine) {
  auto expectError = [](const std::string& name, const std::string& text, const std::string& what) {
    const std::string path = writeFile(name, text);
    try {
      readCameraPath(path);
      ADD_FAILURE() << "accepted " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  expectError("rc_path_b1.json", "{\"keyframes\": []}", "rc_path_b1.json:1: expected {\"keyframes\"");
  expectError("rc_path_b2.json", "{\"keyframes\": [\n {\"origin\": [0,0,0]}]}", "rc_path_b2.json:2: keyframe needs 'target'");
  expectError("rc_path_b3.json", "{\"keyframes\": [\n\n {\"origin\": [0,0,0], \"target\": [0,0,0]}]}",
              ":3: origin and target coincide");
  expectError("rc_path_b4.json", "{\"keyframes\": [{\"origin\": [0,0,1], \"target\": [0,0,0], \"fov\": 200}]}",
              "'fov' must be a number in (0, 180)");
  expectError("rc_path_b5.json", "{\"keyframes\": [{\"origin\": [0,0,1], \"target\": [0,0,0], \"zoom\": 2}]}",
              "unknown keyframe member 'zoom'");
  expectError("rc_path_b6.json", "{\"keyframes\": [{\"origin\": [0,0,1], \n\"target\": [0,0,", ":2: unexpected end of input");
  expectError("rc_path_b7.json", "{\"keyframes\": [{\"origin\": [0,1,0], \"target\": [0,0,0]}]}", "parallel");
  EXPECT_THROW(readCameraPath("/nonexistent/rc_path.json"), Error);
}

}  // namespace
}  // namespace rc
