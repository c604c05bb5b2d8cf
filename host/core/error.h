#pragma once
// One exception type for every user-facing failure. The message is complete and precise
// ("scene.xml:12: <bsdf type=\"foo\">: unknown plugin 'foo'"); main() prints it once and exits non-zero.
#include <stdexcept>
#include <string>

namespace rc {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// Formats "file:line: message" when a location is known, else just the message.
std::string atLocation(const std::string& file, int line, const std::string& message);

}  // namespace rc
