#pragma once
// Helpers for the scene loader tests: a private temporary folder to write scene/mesh files into,
// and assertions on rc::Error messages.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/error.h"
#include "scene/scene_loader.h"

namespace rc::test {

class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("rc_scene_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  // Writes `text` to `name` (sub-folders created) and returns the full path.
  std::string write(const std::string& name, const std::string& text) const {
    const auto p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// A minimal valid scene around `body` (a camera is required); `sensor` replaces the default one.
inline std::string sceneXml(const std::string& body, const std::string& sensor = "<sensor type=\"perspective\"/>") {
  return "<scene version=\"3.0.0\">\n" + sensor + "\n" + body + "\n</scene>\n";
}

// Runs f, expects rc::Error whose message contains every one of `parts`; returns the message.
inline std::string expectError(const std::function<void()>& f, std::initializer_list<std::string> parts) {
  try {
    f();
  } catch (const Error& e) {
    const std::string msg = e.what();
    for (const std::string& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "missing '" << p << "' in: " << msg;
    return msg;
  }
  ADD_FAILURE() << "no rc::Error thrown";
  return "";
}

// Loads `xml` written as scene.xml into `dir`.
inline Scene loadText(const TempDir& dir, const std::string& xml, const LoadOptions& options = {},
                      std::vector<std::string>* warnings = nullptr) {
  return loadScene(dir.write("scene.xml", xml), options, warnings);
}

}  // namespace rc::test
