// Constant and grid volumes (texture/volume.h), and the `volume` texture over them.
#include "texture/volume.h"

#include <algorithm>
#include <cmath>

namespace rc {

Bounds3 unitCubeBounds(const Mat4& toWorld) {
  Bounds3 b{Vec3(INFINITY), Vec3(-INFINITY)};
  for (int corner = 0; corner < 8; ++corner) {
    const Vec4 h = toWorld * Vec4(corner & 1 ? 1.0f : 0.0f, corner & 2 ? 1.0f : 0.0f, corner & 4 ? 1.0f : 0.0f, 1.0f);
    const Vec3 p = Vec3(h) / h.w;
    b.lo = glm::min(b.lo, p);
    b.hi = glm::max(b.hi, p);
  }
  return b;
}

namespace {

class ConstVolume final : public Volume {
 public:
  ConstVolume(const Color& value, const Mat4& toWorld) : value_(value), bounds_(unitCubeBounds(toWorld)) {}
  Color eval(const Vec3&) const override { return value_; }
  Color minimum() const override { return value_; }
  Color maximum() const override { return value_; }
  bool constant() const override { return true; }
  Bounds3 bounds() const override { return bounds_; }

 private:
  Color value_;
  Bounds3 bounds_;
};

// Dr.Jit's wrap of an integer voxel coordinate (drjit/texture.h): clamp to the edge, repeat
// periodically, or mirror with period 2n (the edge voxel repeated at the turn).
int wrapIndex(int i, int n, TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::Clamp:
      return std::clamp(i, 0, n - 1);
    case TextureWrap::Repeat: {
      const int m = i % n;
      return m < 0 ? m + n : m;
    }
    case TextureWrap::Mirror: {
      int m = i % (2 * n);
      if (m < 0) m += 2 * n;
      return m >= n ? 2 * n - 1 - m : m;
    }
  }
  return 0;
}

// floor(x) as an int for any float: far points (and NaN) are held at ±2^30 voxels, where a float has
// no fraction left to interpolate anyway, so the conversion never overflows.
int voxelFloor(float x) {
  constexpr float kLimit = 1073741824.0f;
  const float held = x > -kLimit ? (x < kLimit ? x : kLimit) : -kLimit;
  return static_cast<int>(std::floor(held));
}

class GridVolume final : public Volume {
 public:
  GridVolume(GridVolumeData data, VolumeFilter filter, TextureWrap wrap, const Mat4& toLocal)
      : data_(std::move(data)), filter_(filter), wrap_(wrap), toLocal_(toLocal), bounds_(unitCubeBounds(glm::inverse(toLocal))) {
    min_ = Color(INFINITY);
    max_ = Color(-INFINITY);
    const size_t voxels = data_.values.size() / data_.channels;
    for (size_t i = 0; i < voxels; ++i) {
      const Color c = voxel(i);
      min_ = glm::min(min_, c);
      max_ = glm::max(max_, c);
    }
  }

  Color eval(const Vec3& worldPoint) const override {
    const Vec4 h = toLocal_ * Vec4(worldPoint, 1.0f);
    const Vec3 p = Vec3(h) / h.w;
    int n[3];
    for (int a = 0; a < 3; ++a) n[a] = static_cast<int>(data_.size[a]);
    if (filter_ == VolumeFilter::Nearest) {
      int i[3];
      for (int a = 0; a < 3; ++a) i[a] = wrapIndex(voxelFloor(p[a] * n[a]), n[a], wrap_);
      return at(i[0], i[1], i[2]);
    }
    // Trilinear between the voxel centres around p·n − ½.
    int i0[3], i1[3];
    float f[3];
    for (int a = 0; a < 3; ++a) {
      const float x = p[a] * n[a] - 0.5f;
      const int i = voxelFloor(x);
      f[a] = std::isfinite(x) ? glm::clamp(x - static_cast<float>(i), 0.0f, 1.0f) : 0.0f;
      i0[a] = wrapIndex(i, n[a], wrap_);
      i1[a] = wrapIndex(i + 1, n[a], wrap_);
    }
    Color c(0.0f);
    for (int corner = 0; corner < 8; ++corner) {
      const bool bx = corner & 1, by = corner & 2, bz = corner & 4;
      const float w = (bx ? f[0] : 1.0f - f[0]) * (by ? f[1] : 1.0f - f[1]) * (bz ? f[2] : 1.0f - f[2]);
      c += w * at(bx ? i1[0] : i0[0], by ? i1[1] : i0[1], bz ? i1[2] : i0[2]);
    }
    return c;
  }
  Color minimum() const override { return min_; }
  Color maximum() const override { return max_; }
  Bounds3 bounds() const override { return bounds_; }
  float largestValue() const override { return data_.maxValue >= 0.0f ? data_.maxValue : maxComponent(max_); }

 private:
  Color voxel(size_t i) const {
    const float* v = &data_.values[i * data_.channels];
    return data_.channels == 1 ? Color(v[0]) : Color(v[0], v[1], v[2]);
  }
  Color at(int x, int y, int z) const {
    return voxel((static_cast<size_t>(z) * data_.size[1] + y) * data_.size[0] + x);
  }

  GridVolumeData data_;
  VolumeFilter filter_;
  TextureWrap wrap_;
  Mat4 toLocal_;
  Bounds3 bounds_;
  Color min_, max_;
};

class VolumeTexture final : public Texture {
 public:
  explicit VolumeTexture(VolumePtr volume) : volume_(std::move(volume)) {}
  Color eval(const TexturePoint& point) const override { return volume_->eval(point.position); }
  // Over uv the volume has no mean; the middle of its range stands in (lenient mode only).
  Color mean() const override { return 0.5f * (volume_->minimum() + volume_->maximum()); }
  bool readsPosition() const override { return true; }

 private:
  VolumePtr volume_;
};

}  // namespace

VolumePtr makeConstVolume(const Color& value, const Mat4& toWorld) { return std::make_shared<ConstVolume>(value, toWorld); }

VolumePtr makeGridVolume(GridVolumeData data, VolumeFilter filter, TextureWrap wrap, const Mat4& toLocal) {
  return std::make_shared<GridVolume>(std::move(data), filter, wrap, toLocal);
}

TexturePtr makeVolumeTexture(VolumePtr volume) { return std::make_shared<VolumeTexture>(std::move(volume)); }

}  // namespace rc
