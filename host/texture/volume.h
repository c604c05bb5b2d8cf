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
// | use_grid_bbox | boolean | false     | the file's bounds (min, max) are the cube, to_world after |
// | max_value   | float     | the data's | the largest value (a heterogeneous medium's majorant), ≥ the data's |
// Voxel centres sit at (i + ½)/resolution of the unit cube (Dr.Jit's Texture3f, as Mitsuba's grid
// reads it); a 1-channel grid gives grey. A constvolume takes a to_world too: it places nothing
// but the volume's bounds, which a heterogeneous medium confines itself to.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/math.h"
#include "texture/texture.h"

namespace rc {

// An axis-aligned box in world space.
struct Bounds3 {
  Vec3 lo{0.0f}, hi{0.0f};
};

// The world box around to_world's image of the unit cube (Mitsuba's Volume::bbox).
Bounds3 unitCubeBounds(const Mat4& toWorld);

class Volume {
 public:
  virtual ~Volume() = default;
  virtual Color eval(const Vec3& worldPoint) const = 0;
  // The smallest and largest value of each channel anywhere (what the loader validates).
  virtual Color minimum() const = 0;
  virtual Color maximum() const = 0;
  // The same value everywhere (a float or rgb parameter).
  virtual bool constant() const { return false; }
  // Where the volume is defined: its to_world's unit cube (a heterogeneous medium's extent).
  virtual Bounds3 bounds() const = 0;
  // Mitsuba's Volume::max: the largest value of any channel, or a gridvolume's `max_value` (what a
  // heterogeneous medium's majorant scales).
  virtual float largestValue() const { return maxComponent(maximum()); }
};

using VolumePtr = std::shared_ptr<const Volume>;

VolumePtr makeConstVolume(const Color& value, const Mat4& toWorld = Mat4(1.0f));

enum class VolumeFilter { Trilinear, Nearest };

struct GridVolumeData {
  std::array<uint32_t, 3> size{0, 0, 0};  // voxels along x, y, z
  uint32_t channels = 1;                  // 1 or 3
  std::vector<float> values;              // ((z·size_y + y)·size_x + x)·channels + channel
  float maxValue = -1.0f;                 // Mitsuba's `max_value` where given (≥ 0), else −1
};

// toLocal: world → the grid's unit cube (the inverse of to_world).
VolumePtr makeGridVolume(GridVolumeData data, VolumeFilter filter, TextureWrap wrap, const Mat4& toLocal);

// Mitsuba's `volume` texture: the volume at the shading point's world position (TexturePoint::position).
TexturePtr makeVolumeTexture(VolumePtr volume);

}  // namespace rc
