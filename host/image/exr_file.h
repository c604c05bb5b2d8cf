#pragma once
// OpenEXR files through the OpenEXR library itself (scanline, ZIP, float32 channels on write;
// any pixel type on read, converted to float).
#include <string>

#include "image/image_file.h"

namespace rc {

// Throws rc::Error naming `reportPath` (the file the user asked for; `path` may be a temporary).
void writeExr(const std::string& path, const std::string& reportPath, const ImageChannels& image);
ImageChannels readExr(const std::string& path);

}  // namespace rc
