#pragma once
// Image files as named float channels, by extension:
//   .exr         OpenEXR, read and written directly (the renderer's own format: linear float32)
//   anything else through OpenImageIO, loaded on first use from a module beside the binary
//                (oiio_module.h). OpenImageIO as Debian builds it links ≈ 260 libraries, whose
//                dynamic linking cost every rcache process 0.22 s at start (measured: a program
//                linking only it runs 0.22 s, one linking OpenEXR 0.00 s); renders that write
//                EXR now never pay it.
// Errors: rc::Error naming the path.
#include <string>
#include <vector>

namespace rc {

struct ImageChannels {
  int width = 0, height = 0;
  std::vector<std::string> names;  // one per channel
  std::vector<float> data;         // interleaved: pixel i, channel c at data[i * names.size() + c]
  // Writing: store 8 bits per channel, round(255·clamp(v, 0, 1)) (values already encoded).
  // Reading: the file holds sRGB-encoded values (data holds them decoded to [0, 1], not linearised).
  bool eightBitSrgb = false;
  size_t channels() const { return names.size(); }
};

// Writes `image` to `path` in the format of `formatPath`'s extension: callers write a temporary
// file and rename it (core/atomic_file.h), and messages name `formatPath`, the file asked for.
void writeImageFile(const std::string& path, const std::string& formatPath, const ImageChannels& image);
ImageChannels readImageFile(const std::string& path);

// Lower-case extension with the dot ("" when none).
std::string lowerExtension(const std::string& path);
// Index of the channel named `name`, or -1.
int channelIndex(const ImageChannels& image, const std::string& name);
// The colour channels: R, G, B when so named, else the first three, or the single one three times.
void rgbChannelIndices(const ImageChannels& image, int rgb[3]);

}  // namespace rc
