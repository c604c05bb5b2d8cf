#pragma once
// Reads a lat-long environment image (EXR, or any format OpenImageIO reads) into linear RGB, top row first.
#include <string>
#include <vector>

#include "core/math.h"

namespace rc {

struct EnvImage {
  int width = 0, height = 0;
  std::vector<Color> pixels;  // row-major, top row first
};

// Throws rc::Error("path: what") when the file is missing, unreadable, empty, or holds NaN/Inf.
// Grey images are replicated to RGB; alpha and extra channels are dropped.
EnvImage loadEnvImage(const std::string& path);

}  // namespace rc
