#include "image/exr_file.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <exception>

#include "core/error.h"

namespace rc {

void writeExr(const std::string& path, const std::string& reportPath, const ImageChannels& image) {
  const size_t C = image.channels();
  const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  if (image.width <= 0 || image.height <= 0 || C == 0 || image.data.size() != n * C)
    throw Error(reportPath + ": image has no pixels or inconsistent size");
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer fb;
    const size_t xStride = C * sizeof(float), yStride = xStride * static_cast<size_t>(image.width);
    for (size_t c = 0; c < C; ++c) {
      header.channels().insert(image.names[c], Imf::Channel(Imf::FLOAT));
      // OpenEXR's Slice takes a non-const base pointer but only reads through it when writing.
      char* base = reinterpret_cast<char*>(const_cast<float*>(image.data.data() + c));
      fb.insert(image.names[c], Imf::Slice(Imf::FLOAT, base, xStride, yStride));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(image.height);
  } catch (const std::exception& e) {
    throw Error(reportPath + ": cannot write image (" + e.what() + ")");
  }
}

ImageChannels readExr(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    const long W = static_cast<long>(dw.max.x) - dw.min.x + 1, H = static_cast<long>(dw.max.y) - dw.min.y + 1;
    if (W <= 0 || H <= 0) throw Error(path + ": cannot read image (empty data window)");
    // A hostile header can claim any size: refuse what could not be a real image before allocating.
    if (static_cast<double>(W) * static_cast<double>(H) > double(1u << 28))
      throw Error(path + ": cannot read image (" + std::to_string(W) + "x" + std::to_string(H) + " is too large)");
    ImageChannels image;
    image.width = static_cast<int>(W);
    image.height = static_cast<int>(H);
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
      image.names.push_back(it.name());
    if (image.names.empty()) throw Error(path + ": cannot read image (no channels)");
    const size_t C = image.channels();
    if (static_cast<double>(W) * static_cast<double>(H) * static_cast<double>(C) > double(1u << 30))
      throw Error(path + ": cannot read image (" + std::to_string(C) + " channels of " + std::to_string(W) + "x" +
                  std::to_string(H) + " is too large)");
    image.data.assign(static_cast<size_t>(W) * static_cast<size_t>(H) * C, 0.0f);
    Imf::FrameBuffer fb;
    const size_t xStride = C * sizeof(float), yStride = xStride * static_cast<size_t>(W);
    // The slices are addressed by absolute pixel coordinates: shift the base by the window's origin.
    char* origin = reinterpret_cast<char*>(image.data.data()) - static_cast<ptrdiff_t>(dw.min.x) * static_cast<ptrdiff_t>(xStride) -
                   static_cast<ptrdiff_t>(dw.min.y) * static_cast<ptrdiff_t>(yStride);
    for (size_t c = 0; c < C; ++c)
      fb.insert(image.names[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), xStride, yStride));
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    return image;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(path + ": cannot read image (" + e.what() + ")");
  }
}

}  // namespace rc
