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
// <texture type="mesh_attribute"> (on a BSDF parameter that scales the whole BSDF: diffuse
// `reflectance`, a conductor's `specular_reflectance`)
// | parameter | type   | default | meaning                                                   |
// |-----------|--------|---------|-----------------------------------------------------------|
// | name      | string | —       | vertex_color, face_color, vertex_<prefix>, face_<prefix> (PLY) |
// | scale     | float  | 1       | multiplies the value                                      |
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
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/math.h"
#include "texture/mesh_attribute.h"

namespace rc {

// Where a texture is looked up: the surface coordinates uv (the Vec2 itself) and, on a mesh that
// carries attributes, the triangle's vertices, index and barycentrics (what `mesh_attribute`
// reads). Built from a bare uv only explicitly, so that no surface point loses its mesh unnoticed.
struct TexturePoint : Vec2 {
  TexturePoint() : Vec2(0.0f) {}
  explicit TexturePoint(const Vec2& uv) : Vec2(uv) {}
  // Sets the uv, keeping the mesh data.
  TexturePoint& operator=(const Vec2& uv) {
    Vec2::operator=(uv);
    return *this;
  }
  const MeshAttributes* attributes = nullptr;  // null: not on a mesh with attributes
  glm::uvec3 vertices{0u};                     // the triangle's vertex indices
  uint32_t face = 0;                           // the triangle's index
  Vec2 bary{0.0f};                             // weights of vertices.y and .z (x gets 1 − u − v)
  Vec3 position{0.0f};                         // the world-space point (a `volume` texture reads it)
};

class Texture {
 public:
  virtual ~Texture() = default;
  virtual Color eval(const TexturePoint& point) const = 0;
  // Mitsuba's eval_1, the value of a texture on a scalar parameter (roughness, opacity, blend weight,
  // principled's scalars): the luminance of eval(point) unless the plugin defines it otherwise.
  virtual float eval1(const TexturePoint& point) const { return luminance(eval(point)); }
  // Mean over the unit uv square (what a constant stand-in would be, in lenient mode).
  virtual Color mean() const = 0;
  // Mitsuba's eval_1_grad: (∂/∂u, ∂/∂v) of the luminance of eval(uv), where hasGradient() (a bitmap:
  // the derivative of its bilinear interpolation, zero for nearest filtering); a bumpmap needs it.
  virtual bool hasGradient() const { return false; }
  virtual Vec2 gradient1(const Vec2& /*uv*/) const { return Vec2(0.0f); }
  // Pixels along u and v (Mitsuba's Texture::resolution: 1×1 unless the texture is an image); a
  // projector's aspect ratio is its texture's.
  virtual std::pair<int, int> resolution() const { return {1, 1}; }
  // The attribute a `mesh_attribute` texture reads (empty for every other texture): the loader
  // checks that the shapes it shades carry it.
  virtual std::string meshAttribute() const { return {}; }
  // True for a texture of the world position (TexturePoint::position), not of uv: the planner's uv
  // lattices say nothing about it.
  virtual bool readsPosition() const { return false; }
};

using TexturePtr = std::shared_ptr<const Texture>;

// Affine map of uv (Mitsuba's to_uv): the upper-left 2×3 of `m` acting on (u, v, 1) — a 4×4
// to_uv transform uses its x/y rows and translation column.
struct UvTransform {
  Mat3 m{1.0f};
  Vec2 apply(const Vec2& uv) const { return Vec2(m * Vec3(uv, 1.0f)); }
};

// Mitsuba's mesh_attribute: the attribute `name` (vertex_* or face_*) of the mesh at the point.
TexturePtr makeMeshAttributeTexture(const std::string& name, float scale);

TexturePtr makeCheckerboard(const Color& color0, const Color& color1, const UvTransform& toUv);

enum class TextureFilter { Bilinear, Nearest };
enum class TextureWrap { Repeat, Mirror, Clamp };
// pixels: width·height linear colours, row-major, first row first.
TexturePtr makeBitmapTexture(int width, int height, std::vector<Color> pixels, TextureFilter filter, TextureWrap wrap,
                             const UvTransform& toUv);

}  // namespace rc
