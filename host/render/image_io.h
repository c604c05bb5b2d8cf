#pragma once
// Image files (image/image_file.h: EXR through OpenEXR, the rest through OpenImageIO), by extension:
//   .exr  float32 RGB (AOVs as extra channels "<name>.R/G/B"), linear
//   .hdr  Radiance RGBE, linear
//   .png  8-bit sRGB-encoded, clamped to [0, 1]
// Writes go to a temporary file in the same directory which is then renamed, so a failure never
// leaves a partial file. Unknown extension or unwritable path → rc::Error naming the path.
#include <string>

#include "render/integrator.h"

namespace rc {

void writeImage(const Image& image, const std::string& path);
// Reads RGB (grey images are replicated to RGB; PNG/JPEG are decoded from sRGB to linear) and any
// "<name>.R/G/B" channel triples as AOVs. Throws rc::Error naming the path.
Image readImage(const std::string& path);

// sRGB transfer functions (IEC 61966-2-1).
float linearToSrgb(float v);
float srgbToLinear(float v);

}  // namespace rc
