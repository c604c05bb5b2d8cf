#include "core/properties.h"

#include <limits>

#include "core/error.h"

namespace rc {

const Property* Properties::find(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) return nullptr;
  used_.insert(name);
  return &it->second;
}

static Error typeError(const std::string& name, const char* expected, int line) {
  return Error("parameter '" + name + "' (line " + std::to_string(line) + ") must be " + expected);
}

float Properties::getFloat(const std::string& name, float fallback) const {
  const Property* p = find(name);
  if (!p) return fallback;
  if (p->type != Property::Type::Float && p->type != Property::Type::Integer) throw typeError(name, "a float", p->line);
  return static_cast<float>(p->number);
}

int Properties::getInt(const std::string& name, int fallback) const {
  const Property* p = find(name);
  if (!p) return fallback;
  if (p->type != Property::Type::Integer) throw typeError(name, "an integer", p->line);
  // The parser keeps 64-bit integers; converting one beyond int's range would be undefined.
  if (!(p->number >= double(std::numeric_limits<int>::min()) && p->number <= double(std::numeric_limits<int>::max())))
    throw Error("parameter '" + name + "' (line " + std::to_string(p->line) + ") is out of range for a 32-bit integer");
  return static_cast<int>(p->number);
}

bool Properties::getBool(const std::string& name, bool fallback) const {
  const Property* p = find(name);
  if (!p) return fallback;
  if (p->type != Property::Type::Boolean) throw typeError(name, "a boolean", p->line);
  return p->boolean;
}

std::string Properties::getString(const std::string& name, const std::string& fallback) const {
  const Property* p = find(name);
  if (!p) return fallback;
  if (p->type != Property::Type::String) throw typeError(name, "a string", p->line);
  return p->text;
}

Color Properties::getColor(const std::string& name, const Color& fallback) const {
  const Property* p = find(name);
  if (!p) return fallback;
  if (p->type == Property::Type::Float || p->type == Property::Type::Integer) return Color(static_cast<float>(p->number));
  if (p->type != Property::Type::Rgb) throw typeError(name, "an rgb or float", p->line);
  return p->vec;
}

Vec3 Properties::getVector(const std::string& name, const Vec3& fallback) const {
  const Property* p = find(name);
  if (!p) return fallback;
  if (p->type != Property::Type::Point && p->type != Property::Type::Vector && p->type != Property::Type::Rgb)
    throw typeError(name, "a point or vector", p->line);
  return p->vec;
}

std::vector<std::string> Properties::unusedNames() const {
  std::vector<std::string> out;
  for (const auto& kv : values_)
    if (!used_.count(kv.first)) out.push_back(kv.first);
  return out;
}

int Properties::lineOf(const std::string& name) const {
  auto it = values_.find(name);
  return it == values_.end() ? 0 : it->second.line;
}

}  // namespace rc
