#include "scene/value_parsing.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/error.h"

namespace rc {

static std::string trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

double parseNumber(const std::string& text) {
  const std::string t = trim(text);
  if (t.empty()) throw Error("expected a number, got an empty value");
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (end != t.c_str() + t.size()) throw Error("'" + text + "' is not a number");
  if (!std::isfinite(v) || (errno == ERANGE && std::fabs(v) > 1.0)) throw Error("'" + text + "' is not a finite number");
  return v;
}

long long parseInteger(const std::string& text) {
  const std::string t = trim(text);
  if (t.empty()) throw Error("expected an integer, got an empty value");
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(t.c_str(), &end, 10);
  if (end != t.c_str() + t.size()) throw Error("'" + text + "' is not an integer");
  if (errno == ERANGE) throw Error("integer '" + text + "' is out of range");
  return v;
}

bool parseBoolean(const std::string& text) {
  std::string t = trim(text);
  for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (t == "true" || t == "1") return true;
  if (t == "false" || t == "0") return false;
  throw Error("'" + text + "' is not a boolean (true or false)");
}

std::vector<double> parseNumberList(const std::string& text) {
  std::vector<double> out;
  std::string token;
  auto flush = [&] {
    if (!token.empty()) out.push_back(parseNumber(token));
    token.clear();
  };
  for (char c : text) {
    if (c == ',' || std::isspace(static_cast<unsigned char>(c))) flush();
    else token += c;
  }
  flush();
  return out;
}

// Longest value substitution may produce: far beyond any real attribute, and a <default> chain
// that doubles its value ($a$a) fails here with the file:line of the culprit instead of
// allocating until the process dies.
constexpr size_t kMaxSubstitutedLength = size_t(1) << 20;

static std::string substituteOnce(const std::string& text, const std::map<std::string, std::string>& params,
                                  bool& replaced) {
  replaced = false;
  std::string out;
  for (size_t i = 0; i < text.size();) {
    const bool startsName = i + 1 < text.size() &&
                            (std::isalpha(static_cast<unsigned char>(text[i + 1])) || text[i + 1] == '_');
    if (text[i] != '$' || !startsName) {
      out += text[i++];
      continue;
    }
    size_t j = i + 1;
    while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_')) ++j;
    const std::string name = text.substr(i + 1, j - i - 1);
    auto it = params.find(name);
    if (it == params.end()) throw Error("undefined parameter '$" + name + "'");
    if (out.size() + it->second.size() > kMaxSubstitutedLength)
      throw Error("substituting '$" + name + "' makes the value longer than " + std::to_string(kMaxSubstitutedLength) +
                  " characters");
    out += it->second;
    replaced = true;
    i = j;
  }
  return out;
}

std::string substituteParams(const std::string& text, const std::map<std::string, std::string>& params) {
  // A value may itself name a parameter (-D res='$other'); substitute until nothing is left,
  // with a bound so that a self-reference ($a = "$a") is an error rather than a hang.
  std::string current = text;
  for (int round = 0; round < 16; ++round) {
    if (current.find('$') == std::string::npos) return current;
    bool replaced = false;
    current = substituteOnce(current, params, replaced);
    if (!replaced) return current;  // only '$' signs not followed by a name are left
  }
  throw Error("parameter substitution in '" + text +
              "' does not terminate within 16 rounds (a parameter refers to itself, or a chain of more than 16 names)");
}

}  // namespace rc
