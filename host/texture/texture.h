#pragma once
// Spatially varying parameters (Mitsuba 3 textures), looked up by surface uv. Colours are linear RGB.
//
// <texture type="checkerboard">
// | parameter | type  | default | meaning                                               |
// |-----------|-------|---------|-------------------------------------------------------|
// | color0    | rgb   | 0.4     | where frac(u) > ½ and frac(v) > ½ agree (both or neither) |
// | color1    | rgb   | 0.2     | elsewhere                                             |
// On a scalar parameter (eval1) the squares swap: Mitsuba 3's eval_1 gives color0 where the two
// tests disagree (src/textures/checkerboard.cpp, eval vs eval_1).
// | to_uv     | transform | identity | applied to (u, v) before the lookup             |
//
// <texture type="bitmap">
// | parameter   | type   | default  | meaning                                                  |
// |-------------|--------|----------|----------------------------------------------------------|
// | filename    | string | —        | PNG/JPEG/… through OpenImageIO, EXR directly             |
// | raw         | bool   | false    | keep stored values; else 8-bit sRGB files are linearised |
// | filter_type | string | bilinear | bilinear or nearest                                      |
// | wrap_mode   | string | repeat   | repeat, mirror or clamp                                  |
// | to_uv       | transform | identity | applied to (u, v) before the lookup                   |
// uv (0, 0) is the first pixel of the file's first row (its top-left corner), as in Mitsuba; texel
// centres sit at (i + ½)/width.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/math.h"

namespace rc {

class Texture {
 public:
  virtual ~Texture() = default;
  virtual Color eval(const Vec2& uv) const = 0;
  // Mitsuba's eval_1, the value of a texture on a scalar parameter (roughness, opacity, blend weight,
  // principled's scalars): the luminance of eval(uv) unless the plugin defines it otherwise.
  virtual float eval1(const Vec2& uv) const { return luminance(eval(uv)); }
  // Mean over the unit uv square (what a constant stand-in would be, in lenient mode).
  virtual Color mean() const = 0;
  // Mitsuba's eval_1_grad: (∂/∂u, ∂/∂v) of the luminance of eval(uv), where hasGradient() (a bitmap:
  // the derivative of its bilinear interpolation, zero for nearest filtering); a bumpmap needs it.
  virtual bool hasGradient() const { return false; }
  virtual Vec2 gradient1(const Vec2& /*uv*/) const { return Vec2(0.0f); }
  // Pixels along u and v (Mitsuba's Texture::resolution: 1×1 unless the texture is an image); a
  // projector's aspect ratio is its texture's.
  virtual std::pair<int, int> resolution() const { return {1, 1}; }
};

using TexturePtr = std::shared_ptr<const Texture>;

// Affine map of uv (Mitsuba's to_uv): the upper-left 2×3 of `m` acting on (u, v, 1) — a 4×4
// to_uv transform uses its x/y rows and translation column.
struct UvTransform {
  Mat3 m{1.0f};
  Vec2 apply(const Vec2& uv) const { return Vec2(m * Vec3(uv, 1.0f)); }
};

TexturePtr makeCheckerboard(const Color& color0, const Color& color1, const UvTransform& toUv);

enum class TextureFilter { Bilinear, Nearest };
enum class TextureWrap { Repeat, Mirror, Clamp };
// pixels: width·height linear colours, row-major, first row first.
TexturePtr makeBitmapTexture(int width, int height, std::vector<Color> pixels, TextureFilter filter, TextureWrap wrap,
                             const UvTransform& toUv);

}  // namespace rc
