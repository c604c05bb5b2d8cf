#include "app/integrator_registry.h"

#include "cache/cache_params.h"
#include "cache/rcache_integrator.h"
#include "core/error.h"
#include "scene/integrator_params.h"
#include "render/direct_integrator.h"
#include "render/path_integrator.h"

namespace rc {

namespace {

void readRcacheParamsInto(ParamReader& in, IntegratorSettings& s) {
  readPathParams(in, s);
  readRcacheParams(in);  // checked here, kept by the integrator (makeRcacheIntegrator reads them again)
}

// The path tracer with its default (wavefront) core; the scalar core is the tests' reference.
std::unique_ptr<Integrator> makeDefaultPathIntegrator(const IntegratorSettings& settings) {
  return makePathIntegrator(settings);
}

const std::vector<IntegratorEntry> kEntries = {
    {"path", false, true, readPathParams, makeDefaultPathIntegrator},
    {"volpath", false, true, readPathParams, makeDefaultPathIntegrator},
    {"volpathmis", false, true, readPathParams, makeDefaultPathIntegrator},
    {"direct", false, false, readDirectParams, makeDirectIntegrator},
    // Mitsuba's differentiable integrators, rendered as their primal image (scene/integrator_params.h).
    {"prb", false, true, readPrbParams, makeDefaultPathIntegrator},
    {"prb_basic", false, true, readPrbParams, makeDefaultPathIntegrator},
    {"prb_projective", false, true, readProjectivePrbParams, makeDefaultPathIntegrator},
    {"prbvolpath", false, true, readPrbParams, makeDefaultPathIntegrator},
    {"direct_projective", false, false, readDirectProjectiveParams, makeDefaultPathIntegrator},
    {"rcache", true, false, readRcacheParamsInto, makeRcacheIntegrator},
};

void report(const std::string& message, bool lenient, std::vector<std::string>* warnings) {
  if (!lenient) throw Error(message);
  if (warnings) warnings->push_back(message);
}

}  // namespace

const std::vector<IntegratorEntry>& integratorEntries() { return kEntries; }

const IntegratorEntry* findIntegrator(const std::string& name) {
  for (const IntegratorEntry& e : kEntries)
    if (e.name == name) return &e;
  return nullptr;
}

std::string integratorNames() {
  std::string s;
  for (const IntegratorEntry& e : kEntries) s += (s.empty() ? "" : ", ") + e.name;
  return s;
}

std::vector<std::string> integratorParameterNames(const std::string& name) {
  const IntegratorEntry* e = findIntegrator(name);
  if (!e) return {};
  ParamReader names(nullptr);
  IntegratorSettings probe;
  e->readParams(names, probe);
  return names.names();
}

std::unique_ptr<Integrator> makeIntegrator(IntegratorSettings settings, bool lenient, bool fileParams,
                                           std::vector<std::string>* warnings, const IntegratorEntry** chosen) {
  const std::string at = settings.where.empty() ? std::string() : settings.where + ": ";
  const IntegratorEntry* entry = findIntegrator(settings.type);
  if (!entry) {
    report(at + "unknown integrator '" + settings.type + "' (known: " + integratorNames() + ")", lenient, warnings);
    entry = findIntegrator("path");
    settings.type = "path";
  }
  if (chosen) *chosen = entry;
  ParamReader in(&settings.props);
  try {
    entry->readParams(in, settings);
  } catch (const Error& e) {
    // The last parameter read is the one that failed.
    auto it = in.names().empty() ? settings.paramWhere.end() : settings.paramWhere.find(in.names().back());
    throw Error((it != settings.paramWhere.end() ? it->second + ": " : at) + e.what());
  }
  if (fileParams)
    for (const std::string& name : settings.props.unusedNames()) {
      auto it = settings.paramWhere.find(name);
      const std::string where = it != settings.paramWhere.end() ? it->second + ": " : at;
      std::string known;
      for (const std::string& n : integratorParameterNames(entry->name)) known += (known.empty() ? "" : ", ") + n;
      report(where + "unsupported parameter '" + name + "' (" + entry->name + " reads: " + known + ")", lenient,
             warnings);
    }
  return entry->make(settings);
}

}  // namespace rc
