#include "core/json_reader.h"
#include "core/regular_file.h"

#include <cmath>
#include <cctype>
#include <cstdlib>
#include <fstream>

#include "core/error.h"

namespace rc {

namespace {

constexpr size_t kMaxJsonBytes = size_t(16) << 20;
constexpr int kMaxDepth = 64;

class JsonParser {
 public:
  JsonParser(const std::string& text, const std::string& source) : s_(text), source_(source) {}

  JsonValue document() {
    JsonValue v = value(0);
    skipSpace();
    if (i_ != s_.size()) fail("unexpected text after the JSON value");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& msg) const { throw Error(source_ + ":" + std::to_string(line_) + ": " + msg); }

  void skipSpace() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) {
      if (s_[i_] == '\n') ++line_;
      ++i_;
    }
  }

  bool consume(char c) {
    skipSpace();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }

  void expect(char c) {
    if (!consume(c)) fail(std::string("expected '") + c + "'");
  }

  JsonValue value(int depth) {
    if (depth > kMaxDepth) fail("nesting deeper than 64");
    skipSpace();
    if (i_ >= s_.size()) fail("unexpected end of input");
    JsonValue v;
    v.line = line_;
    const char c = s_[i_];
    if (c == '{') {
      ++i_;
      v.kind = JsonValue::Kind::Object;
      if (consume('}')) return v;
      do {
        skipSpace();
        if (i_ >= s_.size() || s_[i_] != '"') fail("expected a member name in quotes");
        const std::string key = string();
        expect(':');
        if (v.object.count(key)) fail("member '" + key + "' given twice");
        v.object[key] = value(depth + 1);
      } while (consume(','));
      expect('}');
    } else if (c == '[') {
      ++i_;
      v.kind = JsonValue::Kind::Array;
      if (consume(']')) return v;
      do v.array.push_back(value(depth + 1));
      while (consume(','));
      expect(']');
    } else if (c == '"') {
      v.kind = JsonValue::Kind::String;
      v.string = string();
    } else if (word("true")) {
      v.kind = JsonValue::Kind::Bool;
      v.boolean = true;
    } else if (word("false")) {
      v.kind = JsonValue::Kind::Bool;
    } else if (word("null")) {
      v.kind = JsonValue::Kind::Null;
    } else {
      v.kind = JsonValue::Kind::Number;
      v.number = number();
    }
    return v;
  }

  bool word(const char* w) {
    const size_t n = std::char_traits<char>::length(w);
    if (s_.compare(i_, n, w) != 0) return false;
    i_ += n;
    return true;
  }

  std::string string() {
    ++i_;  // opening quote
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      char c = s_[i_++];
      if (c == '\n') fail("line break inside a string");
      if (c == '\\') {
        if (i_ >= s_.size()) break;
        const char e = s_[i_++];
        if (e == 'n') c = '\n';
        else if (e == 't') c = '\t';
        else if (e == '"' || e == '\\' || e == '/') c = e;
        else fail(std::string("unsupported escape '\\") + e + "'");
      }
      out += c;
    }
    if (i_ >= s_.size()) fail("unterminated string");
    ++i_;
    return out;
  }

  double number() {
    const size_t start = i_;
    while (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '-' || s_[i_] == '+' ||
                              s_[i_] == '.' || s_[i_] == 'e' || s_[i_] == 'E'))
      ++i_;
    const std::string text = s_.substr(start, i_ - start);
    char* end = nullptr;
    const double v = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v))
      fail("expected a value, got '" + (text.empty() ? s_.substr(start, 1) : text) + "'");
    return v;
  }

  const std::string& s_;
  std::string source_;
  size_t i_ = 0;
  int line_ = 1;
};

}  // namespace

const JsonValue* JsonValue::find(const std::string& key) const {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &it->second;
}

JsonValue parseJson(const std::string& text, const std::string& source) {
  if (text.size() > kMaxJsonBytes) throw Error(source + ": larger than 16 MiB");
  return JsonParser(text, source).document();
}

JsonValue readJsonFile(const std::string& path) {
  requireRegularFile(path, "JSON file");  // opening a FIFO would block until a writer comes
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open");
  // Reads at most one byte beyond the limit, so a huge file is refused without being read whole.
  std::string text(kMaxJsonBytes + 1, '\0');
  in.read(&text[0], static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(in.gcount()));
  return parseJson(text, path);
}

}  // namespace rc
