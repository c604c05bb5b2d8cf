// RenderStats (declared in render/integrator.h): insertion-ordered key/value lists; setting an
// existing key replaces its value in place so the printed order stays stable.
#include "render/integrator.h"

#include "core/phase_cpu.h"

namespace rc {

namespace {
template <typename V>
void upsert(std::vector<std::pair<std::string, V>>& list, const std::string& key, const V& value) {
  for (auto& kv : list)
    if (kv.first == key) {
      kv.second = value;
      return;
    }
  list.emplace_back(key, value);
}
}  // namespace

void RenderStats::set(const std::string& key, double value) { upsert(numbers, key, value); }
void RenderStats::setText(const std::string& key, const std::string& value) { upsert(texts, key, value); }
void RenderStats::setJson(const std::string& key, const std::string& rawJson) { upsert(json, key, rawJson); }

void RenderStats::setPhaseCpu(const std::string& phase, const PhaseCpu& cpu) {
  set("cpu_" + phase + "_serial_s", cpu.serialS);
  set("cpu_" + phase + "_loops_s", cpu.loopsS);
  set("cpu_" + phase + "_loops_span_at_2_s", cpu.loopsSpanAt2S);
  set("cpu_" + phase + "_other_threads_s", cpu.otherThreadsS);
  set(phase + "_parallel_loops", double(cpu.loops));
  set(phase + "_control_thread_sleeps", double(cpu.sleeps));
}

double RenderStats::get(const std::string& key, double fallback) const {
  for (const auto& kv : numbers)
    if (kv.first == key) return kv.second;
  return fallback;
}

std::string RenderStats::text(const std::string& key) const {
  for (const auto& kv : texts)
    if (kv.first == key) return kv.second;
  return "";
}

}  // namespace rc
