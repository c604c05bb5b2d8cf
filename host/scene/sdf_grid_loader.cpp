#include "scene/sdf_grid_loader.h"

#include "core/error.h"
#include "scene/volume_grid_file.h"

namespace rc {

std::vector<uint32_t> occupiedVoxels(const SdfGrid& grid) {
  std::vector<uint32_t> voxels;
  const uint32_t vx = grid.res[0] - 1, vy = grid.res[1] - 1, vz = grid.res[2] - 1;
  for (uint32_t z = 0; z < vz; ++z)
    for (uint32_t y = 0; y < vy; ++y)
      for (uint32_t x = 0; x < vx; ++x) {
        bool allPositive = true, allNegative = true;
        for (int c = 0; c < 8; ++c) {
          const float f = grid.at(x + (c & 1), y + ((c >> 1) & 1), z + ((c >> 2) & 1));
          allPositive = allPositive && f > 0.0f;
          allNegative = allNegative && f < 0.0f;
        }
        if (!allPositive && !allNegative) voxels.push_back(x + vx * (y + vy * z));
      }
  return voxels;
}

SdfGrid loadSdfGrid(const std::string& path) {
  VolumeGrid vol = readVolumeGrid(path);
  if (vol.channels != 1)
    throw Error(path + ": an sdfgrid needs 1 channel per sample, the file has " + std::to_string(vol.channels));
  static const char* kAxis[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a)
    if (vol.size[a] < 2)
      throw Error(path + ": an sdfgrid needs at least 2 samples along each axis, the file has " +
                  std::to_string(vol.size[a]) + " along " + kAxis[a]);
  // Voxel indices are 32-bit, as Mitsuba's.
  const uint64_t voxelCount = uint64_t(vol.size[0] - 1) * (vol.size[1] - 1) * (vol.size[2] - 1);
  if (voxelCount > 0xFFFFFFFFull) throw Error(path + ": an sdfgrid of more than 2^32 - 1 voxels");
  SdfGrid grid;
  for (int a = 0; a < 3; ++a) grid.res[a] = vol.size[a];
  grid.values = std::make_shared<const std::vector<float>>(std::move(vol.values));
  grid.voxels = std::make_shared<const std::vector<uint32_t>>(occupiedVoxels(grid));
  if (grid.voxels->empty())
    throw Error(path + ": no voxel of the sdfgrid holds a zero (its corner values never change sign), "
                       "so it has no surface");
  return grid;
}

}  // namespace rc
