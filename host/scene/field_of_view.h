#pragma once
// Mitsuba's parse_fov, shared by the perspective sensor and the projector emitter.
#include <string>

#include "scene/element.h"

namespace rc {

// A field of view as written: degrees along `axis` (x, y, diagonal, smaller, larger), before the
// image's aspect ratio resolves the axis.
struct FieldOfView {
  float degrees = 0.0f;
  std::string axis = "x";
};
FieldOfView readFieldOfView(const Element& e);

// Any fov_axis → horizontal fov in degrees. aspect = width / height.
float horizontalFovDegrees(float fovDegrees, const std::string& fovAxis, float aspect);

}  // namespace rc
