#include "app/stats_report.h"

#include <cstdio>

#include "core/json_writer.h"

namespace rc {

void printStats(const RenderStats& stats, std::ostream& out) {
  out << "---- statistics ----\n";
  char line[256];
  for (const auto& kv : stats.texts) {
    std::snprintf(line, sizeof line, "  %-28s %s\n", kv.first.c_str(), kv.second.c_str());
    out << line;
  }
  for (const auto& kv : stats.numbers) {
    std::snprintf(line, sizeof line, "  %-28s %s\n", kv.first.c_str(), jsonNumber(kv.second).c_str());
    out << line;
  }
  for (const auto& kv : stats.json) out << "  " << kv.first << ": " << kv.second << "\n";
  out << "--------------------\n";
}

std::string statsToJson(const RenderStats& stats) {
  JsonWriter w;
  w.beginObject();
  for (const auto& kv : stats.numbers) w.field(kv.first, kv.second);
  for (const auto& kv : stats.texts) w.field(kv.first, kv.second);
  for (const auto& kv : stats.json) w.key(kv.first).raw(kv.second);
  w.endObject();
  return w.str() + "\n";
}

}  // namespace rc
