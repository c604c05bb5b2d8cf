#include "bsdf/bsdf_params.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "core/error.h"

namespace rc {

void throwParamError(const Properties& props, const std::string& name, const std::string& message) {
  std::string where = "parameter '" + name + "'";
  const int line = props.lineOf(name);
  if (line > 0) where += " (line " + std::to_string(line) + ")";
  where += " of <bsdf type=\"" + props.pluginType + "\">";
  throw Error(where + ": " + message);
}

static std::string fmt(float v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", static_cast<double>(v));
  return buf;
}

Color readReflectance(const Properties& props, const std::string& name, float fallback) {
  const Color c = props.getColor(name, Color(fallback));
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(c[i])) throwParamError(props, name, "must be finite, got " + fmt(c[i]));
    if (c[i] < 0.0f) throwParamError(props, name, "must be non-negative, got " + fmt(c[i]));
  }
  return c;
}

float readFloatIn(const Properties& props, const std::string& name, float fallback, float lo, float hi) {
  const float v = props.getFloat(name, fallback);
  if (!std::isfinite(v)) throwParamError(props, name, "must be finite, got " + fmt(v));
  if (v < lo || v > hi) throwParamError(props, name, "must lie in [" + fmt(lo) + ", " + fmt(hi) + "], got " + fmt(v));
  return v;
}

// Mitsuba 3, include/mitsuba/render/ior.h (refractive indices at 589 nm).
struct NamedIor {
  const char* name;
  float value;
};
static const NamedIor kIorTable[] = {
    {"vacuum", 1.0f},          {"helium", 1.000036f},     {"hydrogen", 1.000132f},
    {"air", 1.000277f},        {"carbon dioxide", 1.00045f}, {"water", 1.3330f},
    {"acetone", 1.36f},        {"ethanol", 1.361f},       {"carbon tetrachloride", 1.461f},
    {"glycerol", 1.4729f},     {"benzene", 1.501f},       {"silicone oil", 1.52045f},
    {"bromine", 1.661f},       {"water ice", 1.31f},      {"fused quartz", 1.458f},
    {"pyrex", 1.470f},         {"acrylic glass", 1.49f},  {"polypropylene", 1.49f},
    {"bk7", 1.5046f},          {"sodium chloride", 1.544f}, {"amber", 1.55f},
    {"pet", 1.5750f},          {"diamond", 2.419f},
};

bool lookupIorName(const std::string& name, float* value) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const NamedIor& e : kIorTable)
    if (lower == e.name) {
      *value = e.value;
      return true;
    }
  return false;
}

float readIor(const Properties& props, const std::string& name, const std::string& fallbackName) {
  float value = 0.0f;
  if (!props.has(name)) {
    lookupIorName(fallbackName, &value);
    return value;
  }
  // The value is either a name (string) or a number; the string getter throws on a number.
  std::string text;
  bool isText = true;
  try {
    text = props.getString(name, "");
  } catch (const Error&) {
    isText = false;
  }
  if (isText) {
    if (!lookupIorName(text, &value)) {
      std::string known;
      for (const NamedIor& e : kIorTable) known += std::string(known.empty() ? "" : ", ") + e.name;
      throwParamError(props, name, "unknown index-of-refraction name '" + text + "' (known: " + known + ")");
    }
    return value;
  }
  value = props.getFloat(name, 1.0f);
  if (!std::isfinite(value) || !(value > 0.0f)) throwParamError(props, name, "must be a positive finite number, got " + fmt(value));
  return value;
}

std::string hexFloat(float v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", static_cast<double>(v));
  return buf;
}

std::string hexColor(const Color& c) { return hexFloat(c.r) + "," + hexFloat(c.g) + "," + hexFloat(c.b); }

DielectricParams readDielectricParams(const Properties& props) {
  DielectricParams d;
  d.eta = readIor(props, "int_ior", "bk7") / readIor(props, "ext_ior", "air");
  d.reflectance = readReflectance(props, "specular_reflectance", 1.0f);
  d.transmittance = readReflectance(props, "specular_transmittance", 1.0f);
  return d;
}

std::string DielectricParams::key() const {
  return "eta=" + hexFloat(eta) + ";specular_reflectance=" + hexColor(reflectance) +
         ";specular_transmittance=" + hexColor(transmittance);
}

}  // namespace rc
