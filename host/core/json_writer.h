#pragma once
// The one JSON writer: statistics (--stats), material plans, fill passes and caches lists.
// Output is compact with ", " and ": " separators; numbers print as integers when integral, else
// with 6 significant digits; non-finite numbers as null (JSON has no inf/nan).
#include <string>
#include <type_traits>
#include <vector>

namespace rc {

std::string jsonEscape(const std::string& text);  // without the surrounding quotes
std::string jsonNumber(double v);

class JsonWriter {
 public:
  JsonWriter& beginObject() { return open('{'); }
  JsonWriter& endObject() { return close('}'); }
  JsonWriter& beginArray() { return open('['); }
  JsonWriter& endArray() { return close(']'); }
  JsonWriter& key(const std::string& name);
  JsonWriter& value(double v) { return raw(jsonNumber(v)); }
  JsonWriter& value(bool v) { return raw(v ? "true" : "false"); }
  JsonWriter& value(const std::string& v) { return raw("\"" + jsonEscape(v) + "\""); }
  JsonWriter& value(const char* v) { return value(std::string(v)); }
  // A value that already is JSON text (a nested list built elsewhere).
  JsonWriter& raw(const std::string& json);
  template <typename T>
  JsonWriter& field(const std::string& name, const T& v) {
    key(name);
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) return value(static_cast<double>(v));
    else return value(v);
  }
  const std::string& str() const { return out_; }

 private:
  JsonWriter& open(char c);
  JsonWriter& close(char c);
  void separate();
  std::string out_;
  std::vector<bool> empty_;  // per open container: nothing written into it yet
  bool afterKey_ = false;
};

}  // namespace rc
