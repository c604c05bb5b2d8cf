#pragma once
// Typed plugin parameters as parsed from the scene file, with use-tracking: a factory reads what
// it understands, and the parser reports every parameter nobody read as "unsupported parameter"
// (error, or warning with --lenient), so nothing is silently ignored.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/math.h"

namespace rc {

struct Property {
  enum class Type { Integer, Float, Boolean, String, Rgb, Point, Vector } type = Type::Float;
  double number = 0.0;       // integer, float
  bool boolean = false;
  std::string text;          // string
  Vec3 vec{0.0f};            // rgb, point, vector
  int line = 0;              // source line, for messages
};

class Properties {
 public:
  std::string pluginType;    // e.g. "roughconductor"
  std::string location;      // "file.xml:12" of the owning element, for messages

  void set(const std::string& name, const Property& p) { values_[name] = p; }
  bool has(const std::string& name) const { return values_.count(name) != 0; }

  // Getters mark the parameter used. Type mismatches and out-of-range values throw rc::Error
  // naming the parameter (the parser adds file:line).
  float getFloat(const std::string& name, float fallback) const;
  int getInt(const std::string& name, int fallback) const;
  bool getBool(const std::string& name, bool fallback) const;
  std::string getString(const std::string& name, const std::string& fallback) const;
  Color getColor(const std::string& name, const Color& fallback) const;  // rgb, or float → grey
  Vec3 getVector(const std::string& name, const Vec3& fallback) const;   // point/vector

  // The raw parameter (marked used), null when absent: for readers that convert types themselves.
  const Property* property(const std::string& name) const { return find(name); }

  std::vector<std::string> unusedNames() const;  // set but never read
  int lineOf(const std::string& name) const;

 private:
  std::map<std::string, Property> values_;
  mutable std::set<std::string> used_;
  const Property* find(const std::string& name) const;
};

}  // namespace rc
