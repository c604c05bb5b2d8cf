#pragma once
// Typed scene-file parameters built in code, as the XML loader would make them: the tests that
// build BSDFs, emitters and integrators without a scene file.
#include <string>

#include "core/math.h"
#include "core/properties.h"

namespace rc::test {

inline Property floatProp(double v) {
  Property p;
  p.type = Property::Type::Float;
  p.number = v;
  return p;
}
inline Property stringProp(const std::string& s) {
  Property p;
  p.type = Property::Type::String;
  p.text = s;
  return p;
}
inline Property rgbProp(const Color& c) {
  Property p;
  p.type = Property::Type::Rgb;
  p.vec = c;
  return p;
}
inline Property rgbProp(float r, float g, float b) { return rgbProp(Color(r, g, b)); }

}  // namespace rc::test
