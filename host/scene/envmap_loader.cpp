#include "scene/envmap_loader.h"

#include <filesystem>

#include <OpenImageIO/imageio.h>

#include "core/error.h"

namespace rc {

EnvImage loadEnvImage(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw Error("environment map '" + path + "' not found");
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw Error("cannot read environment map '" + path + "': " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  EnvImage img;
  img.width = spec.width;
  img.height = spec.height;
  const int channels = spec.nchannels;
  if (img.width <= 0 || img.height <= 0 || channels <= 0)
    throw Error("environment map '" + path + "' has no pixels");
  if (size_t(img.width) * size_t(img.height) > (size_t(1) << 28))
    throw Error("environment map '" + path + "' is too large (" + std::to_string(img.width) + "x" + std::to_string(img.height) + ")");
  std::vector<float> raw(size_t(img.width) * img.height * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, raw.data()))
    throw Error("cannot read environment map '" + path + "': " + in->geterror());
  in->close();
  img.pixels.resize(size_t(img.width) * img.height);
  for (size_t i = 0; i < img.pixels.size(); ++i) {
    const float* p = &raw[i * channels];
    const Color c = channels >= 3 ? Color(p[0], p[1], p[2]) : Color(p[0]);
    if (!isFinite(c)) throw Error("environment map '" + path + "' holds NaN or Inf at pixel " + std::to_string(i));
    img.pixels[i] = c;
  }
  return img;
}

}  // namespace rc
