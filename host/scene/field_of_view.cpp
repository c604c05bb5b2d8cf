#include "scene/field_of_view.h"

#include <cmath>
#include <cstdlib>

#include "core/error.h"

namespace rc {

namespace {
constexpr float kDegToRad = kPi / 180.0f;
}

// Mitsuba's parse_fov: either `fov` along `fov_axis`, or a `focal_length` ("<x>mm", default 50mm)
// of a 36×24 mm frame, which fixes the fov on the frame diagonal.
FieldOfView readFieldOfView(const Element& e) {
  FieldOfView fov;
  if (e.props.has("fov") && e.props.has("focal_length"))
    e.failParam("focal_length", "give either 'fov' or 'focal_length', not both");
  if (e.props.has("fov")) {
    fov.degrees = e.located([&] { return e.props.getFloat("fov", 0.0f); });
    if (!(fov.degrees > 0.0f && fov.degrees < 180.0f))
      e.failParam("fov", "'fov' must be in (0, 180) degrees, got " + std::to_string(fov.degrees));
    fov.axis = e.located([&] { return e.props.getString("fov_axis", "x"); });
    if (fov.axis != "x" && fov.axis != "y" && fov.axis != "diagonal" && fov.axis != "smaller" && fov.axis != "larger")
      e.failParam("fov_axis", "'fov_axis' must be x, y, diagonal, smaller or larger, got '" + fov.axis + "'");
  } else {
    std::string focal = e.located([&] { return e.props.getString("focal_length", "50mm"); });
    if (focal.size() > 2 && focal.compare(focal.size() - 2, 2, "mm") == 0) focal.resize(focal.size() - 2);
    char* end = nullptr;
    const double mm = std::strtod(focal.c_str(), &end);
    if (focal.empty() || *end != '\0' || !(mm > 0.0) || !std::isfinite(mm))
      e.failParam("focal_length", "'focal_length' must be a positive length like \"50mm\"");
    fov.degrees = static_cast<float>(2.0 * std::atan(std::sqrt(36.0 * 36.0 + 24.0 * 24.0) / (2.0 * mm)) * 180.0 / kPiD);
    fov.axis = "diagonal";
    e.located([&] { return e.props.getString("fov_axis", "x"); });  // Mitsuba does not read it here
  }
  return fov;
}

float horizontalFovDegrees(float fov, const std::string& axisIn, float aspect) {
  std::string axis = axisIn;
  if (axis == "smaller") axis = aspect > 1.0f ? "y" : "x";
  else if (axis == "larger") axis = aspect > 1.0f ? "x" : "y";
  if (axis == "x") return fov;
  if (axis == "y") return 2.0f * std::atan(std::tan(0.5f * fov * kDegToRad) * aspect) / kDegToRad;
  if (axis == "diagonal") {
    const float diagonal = 2.0f * std::tan(0.5f * fov * kDegToRad);
    const float width = diagonal / std::sqrt(1.0f + 1.0f / (aspect * aspect));
    return 2.0f * std::atan(0.5f * width) / kDegToRad;
  }
  throw Error("perspective sensor: unknown fov_axis '" + axisIn + "' (x, y, diagonal, smaller, larger)");
}

}  // namespace rc
