#include "scene/envmap_loader.h"

#include <filesystem>

#include "core/error.h"
#include "core/regular_file.h"
#include "image/image_file.h"

namespace rc {

EnvImage loadEnvImage(const std::string& path) {
  if (const std::string why = irregularFileReason(path); !why.empty())
    throw Error("environment map '" + path + (why == "not found" ? "' not found" : "': " + why));
  ImageChannels in;
  try {
    in = readImageFile(path);
  } catch (const Error& e) {
    throw Error(std::string("environment map: ") + e.what());
  }
  EnvImage img;
  img.width = in.width;
  img.height = in.height;
  const size_t channels = in.channels();
  if (img.width <= 0 || img.height <= 0 || channels == 0)
    throw Error("environment map '" + path + "' has no pixels");
  if (size_t(img.width) * size_t(img.height) > (size_t(1) << 28))
    throw Error("environment map '" + path + "' is too large (" + std::to_string(img.width) + "x" + std::to_string(img.height) + ")");
  int rgb[3];
  rgbChannelIndices(in, rgb);
  img.pixels.resize(size_t(img.width) * img.height);
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    const float* p = &in.data[i * channels];
    // Colour as stored: an environment map is radiance, taken as linear whatever its file format.
    const Color c(p[rgb[0]], p[rgb[1]], p[rgb[2]]);
    if (!isFinite(c)) throw Error("environment map '" + path + "' holds NaN or Inf at pixel " + std::to_string(i));
    img.pixels[i] = c;
  }
  return img;
}

}  // namespace rc
