#pragma once
// Parameter reading shared by the BSDF plugins: validation with messages naming the parameter,
// Mitsuba's named indices of refraction, and the hex-float text of parameterKey().
#include <string>

#include "core/math.h"
#include "core/properties.h"

namespace rc {

// rc::Error "parameter 'name' (line n) of <bsdf type="t">: message".
[[noreturn]] void throwParamError(const Properties& props, const std::string& name, const std::string& message);

// Colour whose components must be finite and ≥ 0 (reflectances). Float values become grey.
Color readReflectance(const Properties& props, const std::string& name, float fallback);
// Finite float in [lo, hi].
float readFloatIn(const Properties& props, const std::string& name, float fallback, float lo, float hi);
// Index of refraction: a positive finite float, or a material name as in Mitsuba 3's ior.h
// ("bk7", "water", "air", "acrylic glass", "polypropylene", ...). `fallbackName` is the default.
float readIor(const Properties& props, const std::string& name, const std::string& fallbackName);
// Looks up a named IOR (lower-case). Returns false when the name is not in the table.
bool lookupIorName(const std::string& name, float* value);

// The parameters of the smooth dielectric interfaces (dielectric, thindielectric): η = int_ior /
// ext_ior (defaults bk7 / air) and the two multipliers; key() is their parameterKey text.
struct DielectricParams {
  float eta = 1.0f;
  Color reflectance{1.0f}, transmittance{1.0f};
  std::string key() const;
};
DielectricParams readDielectricParams(const Properties& props);

// Exact text of a float ("%a"), so keys differ whenever values differ by one ulp.
std::string hexFloat(float v);
std::string hexColor(const Color& c);

}  // namespace rc
