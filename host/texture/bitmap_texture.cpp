// Image texture lookups as Mitsuba 3's bitmap plugin does them (drjit's Texture): texel centres at
// (i + ½)/size, bilinear weights between the four nearest centres, each index wrapped on its own.
#include <cmath>

#include "core/error.h"
#include "texture/texture.h"

namespace rc {
namespace {

class BitmapTexture final : public Texture {
 public:
  BitmapTexture(int w, int h, std::vector<Color> px, TextureFilter f, TextureWrap wrap, const UvTransform& t)
      : w_(w), h_(h), px_(std::move(px)), filter_(f), wrap_(wrap), toUv_(t) {
    if (w <= 0 || h <= 0 || px_.size() != size_t(w) * size_t(h)) throw Error("bitmap texture: bad pixel array");
    Color sum(0.0f);
    for (const Color& c : px_) sum += c;
    mean_ = sum / static_cast<float>(px_.size());
  }

  Color eval(const TexturePoint& uvIn) const override {
    const Vec2 uv = toUv_.apply(uvIn);
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return mean_;
    const float x = uv.x * static_cast<float>(w_), y = uv.y * static_cast<float>(h_);
    if (filter_ == TextureFilter::Nearest) return texel(floorIndex(x), floorIndex(y));
    const float fx = x - 0.5f, fy = y - 0.5f;
    const float x0 = std::floor(fx), y0 = std::floor(fy);
    const float tx = fx - x0, ty = fy - y0;
    const long ix = static_cast<long>(x0), iy = static_cast<long>(y0);
    return (1.0f - ty) * ((1.0f - tx) * texel(ix, iy) + tx * texel(ix + 1, iy)) +
           ty * ((1.0f - tx) * texel(ix, iy + 1) + tx * texel(ix + 1, iy + 1));
  }
  Color mean() const override { return mean_; }
  bool hasGradient() const override { return true; }
  Vec2 gradient1(const Vec2& uvIn) const override {
    if (filter_ == TextureFilter::Nearest) return Vec2(0.0f);  // zero almost everywhere
    const Vec2 uv = toUv_.apply(uvIn);
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return Vec2(0.0f);
    const float fx = uv.x * static_cast<float>(w_) - 0.5f, fy = uv.y * static_cast<float>(h_) - 0.5f;
    const float x0 = std::floor(fx), y0 = std::floor(fy);
    const float tx = fx - x0, ty = fy - y0;
    const long ix = static_cast<long>(x0), iy = static_cast<long>(y0);
    const float f00 = luminance(texel(ix, iy)), f10 = luminance(texel(ix + 1, iy));
    const float f01 = luminance(texel(ix, iy + 1)), f11 = luminance(texel(ix + 1, iy + 1));
    // Partials along the texel axes, then through the transpose of to_uv's linear part and scaled
    // by the resolution last — the order Mitsuba's eval_1_grad applies them in.
    const float dx = (1.0f - ty) * (f10 - f00) + ty * (f11 - f01);
    const float dy = (1.0f - tx) * (f01 - f00) + tx * (f11 - f10);
    const Mat3& m = toUv_.m;
    return Vec2((m[0][0] * dx + m[0][1] * dy) * static_cast<float>(w_), (m[1][0] * dx + m[1][1] * dy) * static_cast<float>(h_));
  }
  std::pair<int, int> resolution() const override { return {w_, h_}; }

 private:
  // floor as an index, saturated far outside any image so wrapping stays in integer range.
  static long floorIndex(float v) { return static_cast<long>(std::floor(std::fmax(-1e9f, std::fmin(1e9f, v)))); }
  static long wrapIndex(long i, long n, TextureWrap mode) {
    switch (mode) {
      case TextureWrap::Clamp:
        return i < 0 ? 0 : (i >= n ? n - 1 : i);
      case TextureWrap::Mirror: {
        const long period = 2 * n;
        long m = i % period;
        if (m < 0) m += period;
        return m < n ? m : period - 1 - m;
      }
      case TextureWrap::Repeat:
      default: {
        long m = i % n;
        return m < 0 ? m + n : m;
      }
    }
  }
  const Color& texel(long x, long y) const {
    return px_[static_cast<size_t>(wrapIndex(y, h_, wrap_)) * static_cast<size_t>(w_) + static_cast<size_t>(wrapIndex(x, w_, wrap_))];
  }

  int w_, h_;
  std::vector<Color> px_;
  TextureFilter filter_;
  TextureWrap wrap_;
  UvTransform toUv_;
  Color mean_{0.0f};
};

}  // namespace

TexturePtr makeBitmapTexture(int width, int height, std::vector<Color> pixels, TextureFilter filter, TextureWrap wrap,
                             const UvTransform& toUv) {
  return std::make_shared<BitmapTexture>(width, height, std::move(pixels), filter, wrap, toUv);
}

}  // namespace rc
