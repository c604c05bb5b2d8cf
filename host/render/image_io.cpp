#include "render/image_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "core/atomic_file.h"
#include "core/error.h"

namespace rc {

float linearToSrgb(float v) {
  if (!(v > 0.0f)) return 0.0f;
  if (v <= 0.0031308f) return 12.92f * v;
  return 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float v) {
  if (!(v > 0.0f)) return 0.0f;
  if (v <= 0.04045f) return v / 12.92f;
  return std::pow((v + 0.055f) / 1.055f, 2.4f);
}

namespace {

std::string lowerExtension(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void writeWithOiio(const std::string& tmp, const std::string& path, const OIIO::ImageSpec& spec, const void* data) {
  auto out = OIIO::ImageOutput::create(tmp);
  if (!out) throw Error(path + ": cannot write image (" + OIIO::geterror() + ")");
  if (!out->open(tmp, spec)) {
    const std::string why = out->geterror();
    std::remove(tmp.c_str());
    throw Error(path + ": cannot write image (" + why + ")");
  }
  const bool ok = out->write_image(spec.format, data);
  const std::string why = ok ? "" : out->geterror();
  const bool closed = out->close();
  if (!ok || !closed) {
    std::remove(tmp.c_str());
    throw Error(path + ": writing the image failed (" + (ok ? out->geterror() : why) + ")");
  }
}

}  // namespace

void writeImage(const Image& image, const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".exr" && ext != ".png" && ext != ".hdr")
    throw Error(path + ": unknown image extension '" + ext + "' (use .exr, .png or .hdr)");
  const size_t n = static_cast<size_t>(image.width) * image.height;
  if (image.width <= 0 || image.height <= 0 || image.pixels.size() != n)
    throw Error(path + ": image has no pixels or inconsistent size");
  const std::string tmp = temporarySibling(path);

  if (ext == ".png") {
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    std::vector<uint8_t> bytes(n * 3);
    for (size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        const float v = std::min(1.0f, std::max(0.0f, linearToSrgb(image.pixels[i][c])));
        bytes[3 * i + c] = static_cast<uint8_t>(std::lround(v * 255.0f));
      }
    writeWithOiio(tmp, path, spec, bytes.data());
  } else {
    // EXR carries AOVs as extra channels; HDR is RGB only.
    const bool withAovs = ext == ".exr";
    const int channels = 3 + (withAovs ? 3 * static_cast<int>(image.aovs.size()) : 0);
    OIIO::ImageSpec spec(image.width, image.height, channels, OIIO::TypeDesc::FLOAT);
    std::vector<std::string> names = {"R", "G", "B"};
    if (withAovs)
      for (const auto& [name, layer] : image.aovs) {
        if (layer.size() != n) throw Error(path + ": AOV '" + name + "' has the wrong size");
        for (const char* c : {".R", ".G", ".B"}) names.push_back(name + c);
      }
    spec.channelnames = names;
    spec.attribute("oiio:ColorSpace", "Linear");
    std::vector<float> data(n * channels);
    for (size_t i = 0; i < n; ++i) {
      float* px = &data[i * channels];
      for (int c = 0; c < 3; ++c) px[c] = image.pixels[i][c];
      int k = 3;
      if (withAovs)
        for (const auto& [name, layer] : image.aovs)
          for (int c = 0; c < 3; ++c) px[k++] = layer[i][c];
    }
    writeWithOiio(tmp, path, spec, data.data());
  }
  commitTemporary(tmp, path);
}

Image readImage(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw Error(path + ": cannot read image (" + OIIO::geterror() + ")");
  const OIIO::ImageSpec& spec = in->spec();
  Image img;
  img.width = spec.width;
  img.height = spec.height;
  const int channels = spec.nchannels;
  const size_t n = static_cast<size_t>(img.width) * img.height;
  std::vector<float> data(n * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data())) {
    const std::string why = in->geterror();
    throw Error(path + ": cannot read image (" + why + ")");
  }
  const std::string ext = lowerExtension(path);
  const bool srgb = spec.get_string_attribute("oiio:ColorSpace") == "sRGB" || ext == ".png" || ext == ".jpg" ||
                    ext == ".jpeg";
  in->close();

  // Channels by name (OpenEXR stores them alphabetically): colour = R, G, B when named so, else the
  // first three channels (or the single grey channel); alpha is ignored.
  std::map<std::string, int> byName;
  for (int c = 0; c < channels; ++c) byName[spec.channelnames[c]] = c;
  int rgb[3] = {0, channels >= 3 ? 1 : 0, channels >= 3 ? 2 : 0};
  if (byName.count("R") && byName.count("G") && byName.count("B"))
    rgb[0] = byName["R"], rgb[1] = byName["G"], rgb[2] = byName["B"];
  img.pixels.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const float* px = &data[i * channels];
    Color c(px[rgb[0]], px[rgb[1]], px[rgb[2]]);
    if (srgb) c = Color(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b));
    img.pixels[i] = c;
  }
  // AOVs: channel triples named "<name>.R", "<name>.G", "<name>.B".
  for (const auto& [name, index] : byName) {
    if (name.size() < 3 || name.compare(name.size() - 2, 2, ".R") != 0) continue;
    const std::string base = name.substr(0, name.size() - 2);
    if (!byName.count(base + ".G") || !byName.count(base + ".B")) continue;
    const int ci[3] = {index, byName[base + ".G"], byName[base + ".B"]};
    std::vector<Color> layer(n);
    for (size_t i = 0; i < n; ++i)
      layer[i] = Color(data[i * channels + ci[0]], data[i * channels + ci[1]], data[i * channels + ci[2]]);
    img.aovs[base] = std::move(layer);
  }
  return img;
}

}  // namespace rc
