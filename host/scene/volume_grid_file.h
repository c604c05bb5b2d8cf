#pragma once
// Mitsuba's binary volume grid (`.vol`, version 3), read by `gridvolume` and `sdfgrid`: the bytes
// "VOL", uint8 version 3, int32 encoding (1 = float32), int32 resolutions x, y, z, int32 channel
// count, six float32 bounds (min xyz, max xyz), then x·y·z·channels float32 values, x fastest and
// the channels of one voxel together. All little-endian. Mitsuba reads past trailing bytes; so do we.
#include <cstdint>
#include <string>
#include <vector>

namespace rc {

struct VolumeGrid {
  uint32_t size[3] = {0, 0, 0};  // voxels along x, y, z
  uint32_t channels = 0;
  float boundsMin[3] = {0, 0, 0}, boundsMax[3] = {0, 0, 0};  // as written; Mitsuba's plugins ignore them
  std::vector<float> values;  // ((z·size[1] + y)·size[0] + x)·channels + channel

  float at(uint32_t x, uint32_t y, uint32_t z, uint32_t channel) const {
    return values[((static_cast<size_t>(z) * size[1] + y) * size[0] + x) * channels + channel];
  }
};

// Throws rc::Error("<path>: <what is wrong>") for a file that is not a regular file, has the wrong
// magic, version or encoding, a resolution or channel count below 1, fewer value bytes than its
// header promises (checked before anything is allocated), or a non-finite value.
VolumeGrid readVolumeGrid(const std::string& path);

}  // namespace rc
