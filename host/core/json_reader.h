#pragma once
// A small strict JSON reader (objects, arrays, numbers, strings, true/false/null) for the few JSON
// inputs rcache takes (camera paths). Errors name the source and the line: "path.json:3: ...".
// Bounded: input over 16 MiB or nesting deeper than 64 is an error, not a crash.
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rc {

struct JsonValue {
  enum class Kind { Null, Bool, Number, String, Array, Object };
  Kind kind = Kind::Null;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<JsonValue> array;
  std::map<std::string, JsonValue> object;
  int line = 1;  // where the value starts, for messages

  bool isNumber() const { return kind == Kind::Number; }
  bool isArray() const { return kind == Kind::Array; }
  bool isObject() const { return kind == Kind::Object; }
  const JsonValue* find(const std::string& key) const;  // object member or null
};

// Throws rc::Error("<source>:<line>: ...").
JsonValue parseJson(const std::string& text, const std::string& source);
JsonValue readJsonFile(const std::string& path);

}  // namespace rc
