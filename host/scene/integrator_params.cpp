#include "scene/integrator_params.h"

#include <climits>

namespace rc {

void readPathParams(ParamReader& in, IntegratorSettings& settings) {
  settings.maxDepth = in.integer("max_depth", -1, -1, INT_MAX);
  settings.rrDepth = in.integer("rr_depth", 5, 1, INT_MAX);
  settings.hideEmitters = in.flag("hide_emitters", false);
}

void readPrbParams(ParamReader& in, IntegratorSettings& settings) {
  settings.maxDepth = in.integer("max_depth", 6, -1, INT_MAX);
  settings.rrDepth = in.integer("rr_depth", 5, 1, INT_MAX);
  settings.hideEmitters = in.flag("hide_emitters", false);
}

void readProjectivePrbParams(ParamReader& in, IntegratorSettings& settings) {
  readPrbParams(in, settings);
  for (const char* spp : {"sppc", "sppp", "sppi"}) in.integer(spp, 0, 0, INT_MAX);
  in.choice("guiding", "octree", {"none", "grid", "octree"});
  in.flag("guiding_proj", true);
  in.integer("guiding_rounds", 1, 1, INT_MAX);
  in.choice("project_seed", "both", {"both", "bsdf", "emitter"});
}

void readDirectProjectiveParams(ParamReader& in, IntegratorSettings& settings) {
  readProjectivePrbParams(in, settings);
  settings.maxDepth = 2;
  settings.rrDepth = 2;
}

}  // namespace rc
