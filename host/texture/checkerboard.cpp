// Mitsuba 3's checkerboard (src/textures/checkerboard.cpp): its RGB eval gives color0 where the
// fractional parts of u and v are both above ½ or both at most ½, color1 elsewhere; its eval_1 (a
// scalar parameter) the other way round.
#include <cmath>

#include "texture/texture.h"

namespace rc {
namespace {

class Checkerboard final : public Texture {
 public:
  Checkerboard(const Color& c0, const Color& c1, const UvTransform& t) : c0_(c0), c1_(c1), toUv_(t) {}
  Color eval(const TexturePoint& uv) const override { return testsAgree(uv) ? c0_ : c1_; }
  float eval1(const TexturePoint& uv) const override { return luminance(testsAgree(uv) ? c1_ : c0_); }
  Color mean() const override { return 0.5f * (c0_ + c1_); }

 private:
  // Whether frac(u) > ½ and frac(v) > ½ (after to_uv) are both true or both false.
  bool testsAgree(const Vec2& uvIn) const {
    const Vec2 uv = toUv_.apply(uvIn);
    return (uv.x - std::floor(uv.x) > 0.5f) == (uv.y - std::floor(uv.y) > 0.5f);
  }

  Color c0_, c1_;
  UvTransform toUv_;
};

}  // namespace

TexturePtr makeCheckerboard(const Color& color0, const Color& color1, const UvTransform& toUv) {
  return std::make_shared<Checkerboard>(color0, color1, toUv);
}

}  // namespace rc
