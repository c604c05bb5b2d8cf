#pragma once
// Mitsuba 3 volumes (src/volumes/const.cpp, grid.cpp): a colour at every world-space point, read by
// media (albedo, sigma_t) and by the `volume` texture (a volume looked up at the shading point).
//
// <volume type="gridvolume">
// | parameter   | type      | default   | meaning                                                |
// |-------------|-----------|-----------|--------------------------------------------------------|
// | filename    | string    | —         | Mitsuba's `.vol` file (scene/volume_grid_file.h), 1 or 3 channels |
// | filter_type | string    | trilinear | trilinear or nearest                                    |
// | wrap_mode   | string    | clamp     | repeat, mirror or clamp                                 |
// | raw         | boolean   | false     | RGB variants read values as stored either way            |
// | to_world    | transform | identity  | places the grid's unit cube [0,1]³ in the world          |
// Voxel centres sit at (i + ½)/resolution of the unit cube (Dr.Jit's Texture3f, as Mitsuba's grid
// reads it); a 1-channel grid gives grey.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/math.h"
#include "texture/texture.h"

namespace rc {

class Volume {
 public:
  virtual ~Volume() = default;
  virtual Color eval(const Vec3& worldPoint) const = 0;
  // The smallest and largest value of each channel anywhere (what the loader validates).
  virtual Color minimum() const = 0;
  virtual Color maximum() const = 0;
  // The same value everywhere (a float or rgb parameter).
  virtual bool constant() const { return false; }
};

using VolumePtr = std::shared_ptr<const Volume>;

VolumePtr makeConstVolume(const Color& value);

enum class VolumeFilter { Trilinear, Nearest };

struct GridVolumeData {
  std::array<uint32_t, 3> size{0, 0, 0};  // voxels along x, y, z
  uint32_t channels = 1;                  // 1 or 3
  std::vector<float> values;              // ((z·size_y + y)·size_x + x)·channels + channel
};

// toLocal: world → the grid's unit cube (the inverse of to_world).
VolumePtr makeGridVolume(GridVolumeData data, VolumeFilter filter, TextureWrap wrap, const Mat4& toLocal);

// Mitsuba's `volume` texture: the volume at the shading point's world position (TexturePoint::position).
TexturePtr makeVolumeTexture(VolumePtr volume);

}  // namespace rc
