#include "scene/volume_grid_file.h"

#include <cmath>
#include <cstring>
#include <fstream>

#include "core/error.h"
#include "core/regular_file.h"

namespace rc {

namespace {

constexpr size_t kHeaderBytes = 3 + 1 + 4 + 3 * 4 + 4 + 6 * 4;

int32_t int32At(const unsigned char* p) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(p[i]) << (8 * i);
  int32_t s;
  std::memcpy(&s, &v, 4);
  return s;
}

float floatAt(const unsigned char* p) {
  const int32_t bits = int32At(p);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

}  // namespace

VolumeGrid readVolumeGrid(const std::string& path) {
  requireRegularFile(path, "volume grid file");
  auto fail = [&](const std::string& what) { return Error(path + ": " + what); };
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw fail("cannot open volume grid file");
  const auto fileBytes = static_cast<uint64_t>(in.tellg());
  in.seekg(0);
  unsigned char head[kHeaderBytes];
  if (fileBytes < kHeaderBytes || !in.read(reinterpret_cast<char*>(head), kHeaderBytes))
    throw fail("not a Mitsuba volume grid (shorter than its 48-byte header)");
  if (std::memcmp(head, "VOL", 3) != 0) throw fail("not a Mitsuba volume grid (the file does not start with \"VOL\")");
  if (head[3] != 3) throw fail("volume grid version " + std::to_string(head[3]) + " (only version 3 is supported)");
  const int32_t encoding = int32At(head + 4);
  if (encoding != 1) throw fail("volume grid encoding " + std::to_string(encoding) + " (only 1, float32, is supported)");

  const std::string tooShort = "truncated volume grid: its header promises more values than the file holds";
  VolumeGrid grid;
  uint64_t count = 1;
  const char* axes = "xyz";
  for (int a = 0; a < 3; ++a) {
    const int32_t n = int32At(head + 8 + 4 * a);
    if (n < 1) throw fail(std::string("volume grid resolution along ") + axes[a] + " is " + std::to_string(n) + " (must be at least 1)");
    grid.size[a] = static_cast<uint32_t>(n);
    // Compared by division so that a hostile header cannot overflow the product.
    if (static_cast<uint64_t>(n) > fileBytes / count) throw fail(tooShort);
    count *= static_cast<uint64_t>(n);
  }
  const int32_t channels = int32At(head + 20);
  if (channels < 1) throw fail("volume grid channel count " + std::to_string(channels) + " (must be at least 1)");
  grid.channels = static_cast<uint32_t>(channels);
  const uint64_t valueRoom = (fileBytes - kHeaderBytes) / 4;
  if (grid.channels > valueRoom / count) throw fail(tooShort);
  for (int a = 0; a < 3; ++a) {
    grid.boundsMin[a] = floatAt(head + 24 + 4 * a);
    grid.boundsMax[a] = floatAt(head + 36 + 4 * a);
  }
  const uint64_t valueCount = count * grid.channels;

  std::vector<unsigned char> bytes(valueCount * 4);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())))
    throw fail("cannot read the volume grid's values");
  grid.values.resize(valueCount);
  for (uint64_t i = 0; i < valueCount; ++i) {
    grid.values[i] = floatAt(&bytes[i * 4]);
    if (!std::isfinite(grid.values[i])) throw fail("volume grid value " + std::to_string(i) + " is not finite");
  }
  return grid;
}

}  // namespace rc
