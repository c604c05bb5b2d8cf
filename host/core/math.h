#pragma once
// Basic math types: GLM vectors in float for rendering; references use double explicitly.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace rc {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Vec4 = glm::vec4;
using Mat3 = glm::mat3;
using Mat4 = glm::mat4;
using Color = glm::vec3;  // linear RGB

constexpr float kPi = 3.14159265358979323846f;
constexpr float kInvPi = 0.31830988618379067154f;
constexpr double kPiD = 3.14159265358979323846;

inline float luminance(const Color& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }
// True when x, y and z are all finite: 0·v is ±0 for a finite v and NaN for ±∞ or NaN, so the sum is 0
// exactly when all three are finite. One comparison and no branch, so vector loops keep it.
inline bool isFinite(float x, float y, float z) { return 0.0f * x + 0.0f * y + 0.0f * z == 0.0f; }
inline bool isFinite(const Color& c) { return isFinite(c.r, c.g, c.b); }
// std::fmax's result, bit for bit as glibc's fmaxf gives it (the other operand when one is NaN, the
// second when they compare equal, so fmaxf(0,-0) = -0), without its call: on the baseline x86-64
// target GCC does not inline fmax, and the per-sample code calls it several times a vertex.
// (Written as two selects, the second on b's NaN test alone: GCC 12 vectorises loops that use this
// form, render/diffuse_shading.cpp, but not those with a || or with the selects nested the other way.)
inline float fmaxInline(float a, float b) {
  const float larger = a > b ? a : b;
  return b != b ? a : larger;
}
inline float maxComponent(float r, float g, float b) { return fmaxInline(r, fmaxInline(g, b)); }
inline float maxComponent(const Color& c) { return maxComponent(c.r, c.g, c.b); }
// static_cast<int>(std::floor(x)) for |x| < 2³¹ (the caller's range): on the baseline x86-64 target
// (no SSE4.1 round) GCC expands std::floor into a dozen instructions, this is a truncation and a
// compare.
inline int floorToInt(float x) {
  const int t = static_cast<int>(x);
  return x < static_cast<float>(t) ? t - 1 : t;
}
// The largest coordinate magnitude of a point (the scale of its float rounding error).
inline float maxAbs(const Vec3& p) { return std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}); }

}  // namespace rc
