#include "image/image_file.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "core/regular_file.h"
#include "image/exr_file.h"
#include "image/oiio_module.h"

namespace rc {

std::string lowerExtension(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

int channelIndex(const ImageChannels& image, const std::string& name) {
  for (size_t c = 0; c < image.names.size(); ++c)
    if (image.names[c] == name) return static_cast<int>(c);
  return -1;
}

void rgbChannelIndices(const ImageChannels& image, int rgb[3]) {
  const int r = channelIndex(image, "R"), g = channelIndex(image, "G"), b = channelIndex(image, "B");
  if (r >= 0 && g >= 0 && b >= 0) {
    rgb[0] = r, rgb[1] = g, rgb[2] = b;
    return;
  }
  const bool three = image.channels() >= 3;
  rgb[0] = 0, rgb[1] = three ? 1 : 0, rgb[2] = three ? 2 : 0;
}

void writeImageFile(const std::string& path, const std::string& formatPath, const ImageChannels& image) {
  if (lowerExtension(formatPath) == ".exr") {
    writeExr(path, formatPath, image);
    return;
  }
  const std::string why = oiioModule().write(path, formatPath, image);
  if (!why.empty()) throw Error(formatPath + ": cannot write image (" + why + ")");
}

ImageChannels readImageFile(const std::string& path) {
  requireRegularFile(path, "image");
  if (lowerExtension(path) == ".exr") return readExr(path);
  ImageChannels image;
  const std::string why = oiioModule().read(path, image);
  if (!why.empty()) throw Error(path + ": cannot read image (" + why + ")");
  return image;
}

}  // namespace rc
