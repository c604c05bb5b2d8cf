#include "scene/param_reader.h"

#include <cmath>

#include "core/error.h"
#include "scene/value_parsing.h"

namespace rc {

namespace {

std::string textOf(const Property& p) {
  switch (p.type) {
    case Property::Type::String: return p.text;
    case Property::Type::Boolean: return p.boolean ? "true" : "false";
    case Property::Type::Integer: return std::to_string(static_cast<long long>(p.number));
    case Property::Type::Float: return std::to_string(p.number);
    default: return "(a vector)";
  }
}

Error bad(const std::string& name, const Property& p, const std::string& why) {
  return Error("parameter '" + name + "' = '" + textOf(p) + "': " + why);
}

double numberOf(const std::string& name, const Property& p) {
  if (p.type == Property::Type::Float || p.type == Property::Type::Integer) return p.number;
  if (p.type != Property::Type::String) throw bad(name, p, "not a number");
  try {
    return parseNumber(p.text);
  } catch (const Error&) {
    throw bad(name, p, "not a number");
  }
}

}  // namespace

Property textProperty(const std::string& value) {
  Property p;
  p.type = Property::Type::String;
  p.text = value;
  return p;
}

const Property* ParamReader::find(const std::string& name) {
  names_.push_back(name);
  return props_ ? props_->property(name) : nullptr;
}

float ParamReader::real(const std::string& name, float fallback, float lo, float hi) {
  const Property* p = find(name);
  if (!p) return fallback;
  const double x = numberOf(name, *p);
  if (!(x >= lo && x <= hi)) throw bad(name, *p, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<float>(x);
}

int ParamReader::integer(const std::string& name, int fallback, int lo, int hi) {
  const Property* p = find(name);
  if (!p) return fallback;
  double x = 0;
  if (p->type == Property::Type::String) {
    try {
      x = double(parseInteger(p->text));
    } catch (const Error&) {
      throw bad(name, *p, "not an integer");
    }
  } else {
    x = numberOf(name, *p);
    if (x != std::floor(x)) throw bad(name, *p, "not an integer");
  }
  if (!(x >= lo && x <= hi)) throw bad(name, *p, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<int>(x);
}

bool ParamReader::flag(const std::string& name, bool fallback) {
  const Property* p = find(name);
  if (!p) return fallback;
  if (p->type == Property::Type::Boolean) return p->boolean;
  if (p->type == Property::Type::String) {
    if (p->text == "true" || p->text == "1" || p->text == "on") return true;
    if (p->text == "false" || p->text == "0" || p->text == "off") return false;
  }
  throw bad(name, *p, "must be true or false");
}

std::string ParamReader::choice(const std::string& name, const std::string& fallback,
                                std::initializer_list<const char*> options) {
  const Property* p = find(name);
  if (!p) return fallback;
  if (p->type == Property::Type::String)
    for (const char* o : options)
      if (p->text == o) return p->text;
  std::string list;
  for (const char* o : options) list += std::string(list.empty() ? "" : ", ") + o;
  throw bad(name, *p, "must be one of " + list);
}

}  // namespace rc
