#pragma once
// <transform name="..."> → 4×4 matrix. Children compose in the order written: each new operation
// is applied after the previous ones (M = T_new · M), as in Mitsuba.
//   translate x y z | value="x, y, z"      rotate value="x, y, z" | x y z, angle (degrees)
//   scale value="s" | value="x, y, z" | x y z     matrix value="16 or 9 numbers, row-major"
//   lookat origin target [up]
#include <functional>
#include <string>

#include <pugixml.hpp>

#include "core/math.h"

namespace rc {

// `where(node)` gives the "file:line: <element>" prefix for an error at that node.
Mat4 parseTransform(const pugi::xml_node& transform, const std::function<std::string(const pugi::xml_node&)>& where);

// Rotation by `angle` radians about `axis` taken as given (Mitsuba 3: a non-unit axis also scales).
Mat4 rotationAboutAxis(const Vec3& axis, float angle);

// Mitsuba's look-at: local +z toward target, local +y close to up, local +x = up × dir.
Mat4 lookAt(const Vec3& origin, const Vec3& target, const Vec3& up);

}  // namespace rc
