#include "app/stats_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace rc {

std::string jsonEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out;
}

static std::string formatNumber(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  if (v == std::floor(v) && std::fabs(v) < 1e15) std::snprintf(buf, sizeof buf, "%.0f", v);
  else std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void printStats(const RenderStats& stats, std::ostream& out) {
  out << "---- statistics ----\n";
  char line[256];
  for (const auto& kv : stats.texts) {
    std::snprintf(line, sizeof line, "  %-28s %s\n", kv.first.c_str(), kv.second.c_str());
    out << line;
  }
  for (const auto& kv : stats.numbers) {
    std::snprintf(line, sizeof line, "  %-28s %s\n", kv.first.c_str(), formatNumber(kv.second).c_str());
    out << line;
  }
  for (const auto& kv : stats.json) out << "  " << kv.first << ": " << kv.second << "\n";
  out << "--------------------\n";
}

std::string statsToJson(const RenderStats& stats) {
  std::ostringstream s;
  s << "{";
  bool first = true;
  auto sep = [&]() {
    if (!first) s << ", ";
    first = false;
  };
  for (const auto& kv : stats.numbers) {
    sep();
    s << "\"" << jsonEscape(kv.first) << "\": " << formatNumber(kv.second);
  }
  for (const auto& kv : stats.texts) {
    sep();
    s << "\"" << jsonEscape(kv.first) << "\": \"" << jsonEscape(kv.second) << "\"";
  }
  for (const auto& kv : stats.json) {
    sep();
    s << "\"" << jsonEscape(kv.first) << "\": " << kv.second;
  }
  s << "}\n";
  return s.str();
}

}  // namespace rc
