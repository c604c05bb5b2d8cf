#include "scene/transform_parser.h"

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "scene/value_parsing.h"

namespace rc {

namespace {

struct OpReader {
  const pugi::xml_node& node;
  const std::function<std::string(const pugi::xml_node&)>& where;

  [[noreturn]] void fail(const std::string& msg) const { throw Error(where(node) + ": " + msg); }

  template <class F>
  auto guarded(F f) const {
    try {
      return f();
    } catch (const Error& e) {
      fail(e.what());
    }
  }

  bool has(const char* name) const { return static_cast<bool>(node.attribute(name)); }
  double number(const char* name, double fallback) const {
    const pugi::xml_attribute a = node.attribute(name);
    if (!a) return fallback;
    return guarded([&] { return parseNumber(a.value()); });
  }
  std::vector<double> list(const char* name) const {
    return guarded([&] { return parseNumberList(node.attribute(name).value()); });
  }
  Vec3 vec3(const char* name) const {
    const std::vector<double> v = list(name);
    if (v.size() != 3) fail(std::string("attribute '") + name + "' needs 3 numbers, got " + std::to_string(v.size()));
    return Vec3(float(v[0]), float(v[1]), float(v[2]));
  }
  // value="x, y, z" or separate x/y/z attributes (missing ones take `fallback`).
  Vec3 xyz(double fallback) const {
    if (has("value")) {
      if (has("x") || has("y") || has("z")) fail("give either 'value' or x/y/z, not both");
      return vec3("value");
    }
    return Vec3(float(number("x", fallback)), float(number("y", fallback)), float(number("z", fallback)));
  }
  void onlyAttributes(std::initializer_list<const char*> allowed) const {
    for (const pugi::xml_attribute& a : node.attributes()) {
      bool ok = false;
      for (const char* name : allowed) ok = ok || std::string(a.name()) == name;
      if (!ok) fail(std::string("unsupported attribute '") + a.name() + "'");
    }
  }
};

bool finite(const Mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

}  // namespace

Mat4 rotationAboutAxis(const Vec3& a, float angle) {
  // Rodrigues' matrix c·I + (1 − c)·a·aᵀ + s·[a]× with `a` as given, not normalised: Mitsuba 3
  // (drjit's rotate) does the same, so a non-unit axis also scales, and scenes rely on that.
  const float c = std::cos(angle), s = std::sin(angle), k = 1.0f - c;
  Mat4 m(1.0f);  // m[col][row]
  m[0] = Vec4(a.x * a.x * k + c, a.y * a.x * k + a.z * s, a.z * a.x * k - a.y * s, 0.0f);
  m[1] = Vec4(a.x * a.y * k - a.z * s, a.y * a.y * k + c, a.z * a.y * k + a.x * s, 0.0f);
  m[2] = Vec4(a.x * a.z * k + a.y * s, a.y * a.z * k - a.x * s, a.z * a.z * k + c, 0.0f);
  return m;
}

Mat4 lookAt(const Vec3& origin, const Vec3& target, const Vec3& up) {
  const Vec3 dir = glm::normalize(target - origin);
  const Vec3 left = glm::normalize(glm::cross(up, dir));
  const Vec3 newUp = glm::cross(dir, left);
  Mat4 m(1.0f);  // glm is column-major: m[c] is column c
  m[0] = Vec4(left, 0.0f);
  m[1] = Vec4(newUp, 0.0f);
  m[2] = Vec4(dir, 0.0f);
  m[3] = Vec4(origin, 1.0f);
  return m;
}

Mat4 parseTransform(const pugi::xml_node& transform, const std::function<std::string(const pugi::xml_node&)>& where) {
  Mat4 m(1.0f);
  for (const pugi::xml_node& child : transform.children()) {
    if (child.type() != pugi::node_element) continue;
    const OpReader op{child, where};
    const std::string tag = child.name();
    Mat4 t(1.0f);
    if (tag == "translate") {
      op.onlyAttributes({"x", "y", "z", "value"});
      t = glm::translate(Mat4(1.0f), op.xyz(0.0));
    } else if (tag == "scale") {
      op.onlyAttributes({"x", "y", "z", "value"});
      Vec3 s;
      if (op.has("value") && op.list("value").size() == 1 && !(op.has("x") || op.has("y") || op.has("z")))
        s = Vec3(float(op.list("value")[0]));
      else
        s = op.xyz(1.0);
      t = glm::scale(Mat4(1.0f), s);
    } else if (tag == "rotate") {
      op.onlyAttributes({"x", "y", "z", "axis", "value", "angle"});
      Vec3 axis;
      if (op.has("axis") || op.has("value")) {
        const char* name = op.has("axis") ? "axis" : "value";
        if (op.has("x") || op.has("y") || op.has("z") || (op.has("axis") && op.has("value")))
          op.fail(std::string("give either '") + name + "' or x/y/z, not both");
        axis = op.vec3(name);
      } else {
        axis = Vec3(float(op.number("x", 0)), float(op.number("y", 0)), float(op.number("z", 0)));
      }
      if (!op.has("angle")) op.fail("missing attribute 'angle' (degrees)");
      if (glm::dot(axis, axis) == 0.0f) op.fail("rotation axis is zero");
      t = rotationAboutAxis(axis, glm::radians(float(op.number("angle", 0))));
    } else if (tag == "matrix") {
      op.onlyAttributes({"value"});
      if (!op.has("value")) op.fail("missing attribute 'value'");
      const std::vector<double> v = op.list("value");
      if (v.size() == 16) {
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c) t[c][r] = float(v[r * 4 + c]);
      } else if (v.size() == 9) {
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) t[c][r] = float(v[r * 3 + c]);
      } else {
        op.fail("matrix needs 16 or 9 numbers (row-major), got " + std::to_string(v.size()));
      }
    } else if (tag == "lookat") {
      op.onlyAttributes({"origin", "target", "up"});
      if (!op.has("origin") || !op.has("target")) op.fail("lookat needs 'origin' and 'target'");
      const Vec3 origin = op.vec3("origin"), target = op.vec3("target");
      const Vec3 dir = target - origin;
      if (glm::dot(dir, dir) == 0.0f) op.fail("lookat origin and target coincide");
      Vec3 up;
      if (op.has("up")) {
        up = op.vec3("up");
      } else {
        // Mitsuba picks any up perpendicular to the view direction when none is given.
        const Vec3 d = glm::normalize(dir);
        up = std::fabs(d.y) < 0.9f ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
      }
      const Vec3 c = glm::cross(up, glm::normalize(dir));
      if (!(glm::dot(c, c) > 1e-12f)) op.fail("lookat 'up' is parallel to the view direction");
      t = lookAt(origin, target, up);
    } else {
      op.fail("unknown transform operation <" + tag + ">");
    }
    m = t * m;
    if (!finite(m)) op.fail("transform is not finite (NaN or Inf)");
  }
  return m;
}

}  // namespace rc
