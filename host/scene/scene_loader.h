#pragma once
// Loads a Mitsuba 3 XML scene (the subset of ARCHITECTURE.md §Scene format) into a Scene.
#include <map>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace rc {

struct LoadOptions {
  std::map<std::string, std::string> defines;  // -D name=value, override <default>
  bool lenient = false;                        // unsupported plugin/parameter → warning, not error
};

// Throws rc::Error("file:line: <element ...>: what is wrong") on any problem. Warnings (lenient
// mode) are appended to `warnings` when given.
Scene loadScene(const std::string& path, const LoadOptions& options = {},
                std::vector<std::string>* warnings = nullptr);

}  // namespace rc
