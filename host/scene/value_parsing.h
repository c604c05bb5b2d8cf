#pragma once
// Strict text → value conversions for scene attributes. Each throws rc::Error with a message
// naming the offending text (the caller prefixes file:line and the element). NaN and Inf are
// rejected everywhere: no scene quantity is meaningfully infinite, and a NaN would travel silently.
#include <map>
#include <string>
#include <vector>

namespace rc {

double parseNumber(const std::string& text);                  // one finite float
long long parseInteger(const std::string& text);              // decimal integer, whole text
bool parseBoolean(const std::string& text);                   // true/false (also 1/0)
std::vector<double> parseNumberList(const std::string& text); // separated by commas and/or spaces

// Replaces every $name (name = [A-Za-z_][A-Za-z0-9_]*) by params[name]; an undefined name throws
// "undefined parameter '$name'". A '$' not followed by a name is kept as is. Values that name
// parameters themselves are substituted in turn (bounded: self-reference is an error).
std::string substituteParams(const std::string& text, const std::map<std::string, std::string>& params);

}  // namespace rc
