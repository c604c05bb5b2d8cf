#include "app/integrator_overrides.h"

#include "cache/cache_params.h"
#include "core/error.h"
#include "scene/value_parsing.h"

namespace rc {

void applyIntegratorOptions(const RenderArgs& args, const std::string& integrator, IntegratorSettings& s) {
  const bool path = integrator == "path";
  if (path) {
    if (!args.cacheSave.empty()) throw Error("--cache-save: only with the rcache integrator (this render uses path)");
    if (!args.cacheLoad.empty()) throw Error("--cache-load: only with the rcache integrator (this render uses path)");
    if (!args.aovs.empty()) throw Error("--aov " + args.aovs.front() + ": only with the rcache integrator (this render uses path)");
  }
  for (const auto& [name, value] : args.defines) {
    if (!isIntegratorParamName(name)) continue;  // a scene parameter ($name)
    const std::string flag = "-D " + name + "=" + value;
    if (name == "max_depth") {
      s.maxDepth = static_cast<int>(parseInteger(flag, value, -1, 1 << 20));
    } else if (name == "rr_depth") {
      s.rrDepth = static_cast<int>(parseInteger(flag, value, 1, 1 << 20));
    } else if (name == "hide_emitters") {
      try {
        s.hideEmitters = parseBoolean(value);
      } catch (const Error& e) {
        throw Error(flag + ": " + e.what());
      }
    } else if (path) {
      throw Error(flag + ": '" + name + "' is an rcache parameter, but this render uses the path integrator");
    }
    s.params[name] = value;
    s.paramWhere.erase(name);  // now from the command line, named by the message above
  }
  // The rcache integrator checks its parameters when it starts, by name only: check each one
  // written in the file here, so a bad value is reported at its file:line.
  if (integrator != "rcache") return;
  for (const auto& [name, value] : s.params) {
    const auto where = s.paramWhere.find(name);
    const std::string prefix = where != s.paramWhere.end() ? where->second + ": " : "-D " + name + "=" + value + ": ";
    try {
      parseRcacheParams({{name, value}});
    } catch (const Error& e) {
      throw Error(prefix + e.what());
    }
  }
}

}  // namespace rc
