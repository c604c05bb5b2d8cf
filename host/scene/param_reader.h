#pragma once
// Reads a plugin's parameters from its Properties with the default and the valid range written
// once, at the read: the integrators (render/integrator_registry.h) read every parameter through
// it. Values may be typed (<float name="a" value="0.3"/>) or text (-D a=0.3 on the command line,
// stored as a string property): text is parsed as the type the read asks for. Every read marks the
// parameter used, so the unused ones can be reported as unsupported; a ParamReader over no
// Properties reads nothing and only records the names and kinds read (the -D routing asks an
// integrator for its parameter names that way).
#include <initializer_list>
#include <string>
#include <vector>

#include "core/properties.h"

namespace rc {

class ParamReader {
 public:
  explicit ParamReader(const Properties* props) : props_(props) {}

  // Throw rc::Error("parameter 'name' = 'text': why") for a malformed or out-of-range value.
  float real(const std::string& name, float fallback, float lo, float hi);
  int integer(const std::string& name, int fallback, int lo, int hi);
  bool flag(const std::string& name, bool fallback);
  std::string choice(const std::string& name, const std::string& fallback, std::initializer_list<const char*> options);

  // Whether `name` is written at all (a read of it with a default cannot tell); marks nothing.
  bool given(const std::string& name) const { return props_ && props_->has(name); }

  const std::vector<std::string>& names() const { return names_; }  // every parameter read, in order

 private:
  const Property* find(const std::string& name);
  const Properties* props_;
  std::vector<std::string> names_;
};

// A -D name=value override or a test's text parameter: a string property parsed on read.
Property textProperty(const std::string& value);

}  // namespace rc
