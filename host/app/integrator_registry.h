#pragma once
// The integrators by name: what `<integrator type="...">` and `--integrator` accept, how each is
// made, and which parameters it reads (so -D name=value reaches an integrator exactly when the
// name is one of its parameters). Adding an integrator = one entry in integrator_registry.cpp.
//
//   path        unidirectional path tracer (render/path_integrator.h), the ground truth
//   volpath     Mitsuba's volumetric path tracer; without participating media (rcache has none) it
//   volpathmis  is the path tracer, and renders as `path` with the same parameters
//   direct      Mitsuba's direct integrator (render/direct_integrator.h): visible emission plus
//               emitter_samples light and bsdf_samples BSDF samples at the first hit,
//               MIS-combined, no indirect light
//   rcache      radiance caching (cache/rcache_integrator.h)
#include <memory>
#include <string>
#include <vector>

#include "render/integrator.h"
#include "scene/param_reader.h"
#include "scene/scene.h"

namespace rc {

struct IntegratorEntry {
  std::string name;
  bool usesKernels = false;  // needs an SH backend (RcacheIntegrator::setBackend)
  bool pathFamily = false;   // `--integrator auto` may render it with rcache (same estimate, cached)
  // Reads every parameter the integrator takes (marking it used; with a ParamReader over no
  // Properties it only lists them) into `settings`, checking values and ranges.
  void (*readParams)(ParamReader& in, IntegratorSettings& settings);
  // Makes the integrator from settings that readParams filled.
  std::unique_ptr<Integrator> (*make)(const IntegratorSettings& settings);
};

const std::vector<IntegratorEntry>& integratorEntries();
const IntegratorEntry* findIntegrator(const std::string& name);
std::string integratorNames();  // "path, volpath, ..." for messages

// The names of the parameters integrator `name` reads (empty for an unknown name).
std::vector<std::string> integratorParameterNames(const std::string& name);

// Makes `settings.type`. Unknown types and parameters the integrator did not read are errors with
// their file:line (with `lenient`: warnings into `warnings`, and an unknown type renders as path).
// `fileParams` false: the parameters came from the file's integrator of another type
// (--integrator override) and those the chosen one does not read are dropped without a message.
std::unique_ptr<Integrator> makeIntegrator(IntegratorSettings settings, bool lenient, bool fileParams,
                                           std::vector<std::string>* warnings, const IntegratorEntry** chosen = nullptr);

}  // namespace rc
