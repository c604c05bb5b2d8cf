// rcache's OpenImageIO module: every image format except EXR (image/image_file.h says why this is
// a module loaded on demand rather than a library linked into the binary).
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdint>

#include "image/oiio_module_api.h"

namespace {

// Lower-case extension with the dot (the module links nothing of rcache but its headers).
std::string extensionOf(const std::string& path) {
  const size_t slash = path.find_last_of('/'), dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

std::string writeImage(const std::string& path, const std::string& formatPath, const rc::ImageChannels& image) {
  const size_t C = image.channels();
  const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  if (image.width <= 0 || image.height <= 0 || C == 0 || image.data.size() != n * C)
    return "image has no pixels or inconsistent size";
  // The format follows the requested name (the file written may be a temporary without it).
  auto out = OIIO::ImageOutput::create(formatPath);
  if (!out) return OIIO::geterror();
  OIIO::ImageSpec spec(image.width, image.height, static_cast<int>(C),
                       image.eightBitSrgb ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  spec.channelnames = image.names;
  spec.attribute("oiio:ColorSpace", image.eightBitSrgb ? "sRGB" : "Linear");
  std::vector<uint8_t> bytes;
  if (image.eightBitSrgb) {
    bytes.resize(image.data.size());
    for (size_t i = 0; i < bytes.size(); ++i)
      bytes[i] = static_cast<uint8_t>(std::lround(std::min(1.0f, std::max(0.0f, image.data[i])) * 255.0f));
  }
  if (!out->open(path, spec)) {
    const std::string why = out->geterror();
    std::remove(path.c_str());
    return why.empty() ? "cannot open for writing" : why;
  }
  const bool ok = image.eightBitSrgb ? out->write_image(OIIO::TypeDesc::UINT8, bytes.data())
                                     : out->write_image(OIIO::TypeDesc::FLOAT, image.data.data());
  std::string why = ok ? "" : out->geterror();
  if (!out->close() && why.empty()) why = out->geterror();
  if (!ok || !why.empty()) {
    std::remove(path.c_str());
    return why.empty() ? "write failed" : why;
  }
  return "";
}

std::string readImage(const std::string& path, rc::ImageChannels& image) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) return "no pixels";
  if (double(spec.width) * double(spec.height) * double(spec.nchannels) > double(1u << 30)) return "image too large";
  image.width = spec.width;
  image.height = spec.height;
  image.names.assign(spec.channelnames.begin(), spec.channelnames.end());
  image.names.resize(static_cast<size_t>(spec.nchannels));
  for (size_t c = 0; c < image.names.size(); ++c)
    if (image.names[c].empty()) image.names[c] = "channel" + std::to_string(c);
  image.data.assign(static_cast<size_t>(spec.width) * spec.height * spec.nchannels, 0.0f);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.data.data())) {
    const std::string why = in->geterror();
    return why.empty() ? "read failed" : why;
  }
  const std::string ext = extensionOf(path);
  // As Mitsuba's Bitmap readers: PNG, JPEG, BMP, TGA and PPM files hold 8-bit sRGB.
  image.eightBitSrgb = spec.get_string_attribute("oiio:ColorSpace") == "sRGB" || ext == ".png" || ext == ".jpg" ||
                       ext == ".jpeg" || ext == ".bmp" || ext == ".tga" || ext == ".ppm";
  in->close();
  return "";
}

const rc::OiioModuleApi kApi{rc::kOiioModuleAbi, &writeImage, &readImage};

}  // namespace

extern "C" __attribute__((visibility("default"))) const rc::OiioModuleApi* rc_oiio_module_api() { return &kApi; }
