#include "render/image_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/atomic_file.h"
#include "core/error.h"
#include "image/image_file.h"

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

// A codec's success is not proof of a whole file: OpenImageIO's PNG writer reports no error when
// the disk fills (a truncated, unreadable PNG). Decode the temporary completely before it may
// replace anything; the cost is one read of a file just written, small beside any render.
void verifyWrittenImage(const std::string& tmp, const std::string& path, const ImageChannels& written) {
  ImageChannels back;
  try {
    back = readImageFile(tmp);
  } catch (const Error& e) {
    throw Error(path + ": the written image does not read back (disk full?): " + e.what());
  }
  if (back.width != written.width || back.height != written.height || back.channels() != written.channels())
    throw Error(path + ": the written image does not read back whole (disk full?)");
}

}  // namespace

void writeImage(const Image& image, const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".exr" && ext != ".png" && ext != ".hdr")
    throw Error(path + ": unknown image extension '" + ext + "' (use .exr, .png or .hdr)");
  const size_t n = static_cast<size_t>(image.width) * image.height;
  if (image.width <= 0 || image.height <= 0 || image.pixels.size() != n)
    throw Error(path + ": image has no pixels or inconsistent size");
  ImageChannels out;
  out.width = image.width;
  out.height = image.height;
  out.names = {"R", "G", "B"};
  // EXR carries AOVs as extra channels; HDR and PNG are RGB only.
  const bool withAovs = ext == ".exr";
  if (withAovs)
    for (const auto& [name, layer] : image.aovs) {
      if (layer.size() != n) throw Error(path + ": AOV '" + name + "' has the wrong size");
      for (const char* c : {".R", ".G", ".B"}) out.names.push_back(name + c);
    }
  out.eightBitSrgb = ext == ".png";
  const size_t C = out.channels();
  out.data.resize(n * C);
  for (size_t i = 0; i < n; ++i) {
    float* px = &out.data[i * C];
    for (int c = 0; c < 3; ++c) px[c] = out.eightBitSrgb ? linearToSrgb(image.pixels[i][c]) : image.pixels[i][c];
    size_t k = 3;
    if (withAovs)
      for (const auto& [name, layer] : image.aovs)
        for (int c = 0; c < 3; ++c) px[k++] = layer[i][c];
  }
  const std::string tmp = beginTemporary(path);
  try {
    writeImageFile(tmp, path, out);
    syncTemporary(tmp, path);
    verifyWrittenImage(tmp, path, out);
  } catch (...) {
    abandonTemporary(tmp);
    throw;
  }
  commitTemporary(tmp, path);
}

Image readImage(const std::string& path) {
  const ImageChannels in = readImageFile(path);
  Image img;
  img.width = in.width;
  img.height = in.height;
  const size_t C = in.channels(), n = static_cast<size_t>(img.width) * img.height;
  int rgb[3];
  rgbChannelIndices(in, rgb);
  img.pixels.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const float* px = &in.data[i * C];
    Color c(px[rgb[0]], px[rgb[1]], px[rgb[2]]);
    if (in.eightBitSrgb) c = Color(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b));
    img.pixels[i] = c;
  }
  // AOVs: channel triples named "<name>.R", "<name>.G", "<name>.B".
  for (size_t r = 0; r < C; ++r) {
    const std::string& name = in.names[r];
    if (name.size() < 3 || name.compare(name.size() - 2, 2, ".R") != 0) continue;
    const std::string base = name.substr(0, name.size() - 2);
    const int g = channelIndex(in, base + ".G"), b = channelIndex(in, base + ".B");
    if (g < 0 || b < 0) continue;
    std::vector<Color> layer(n);
    for (size_t i = 0; i < n; ++i) layer[i] = Color(in.data[i * C + r], in.data[i * C + g], in.data[i * C + b]);
    img.aovs[base] = std::move(layer);
  }
  return img;
}

}  // namespace rc
