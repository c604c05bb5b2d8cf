#include "scene/integrator_params.h"

#include <climits>

namespace rc {

void readPathParams(ParamReader& in, IntegratorSettings& settings) {
  settings.maxDepth = in.integer("max_depth", -1, -1, INT_MAX);
  settings.rrDepth = in.integer("rr_depth", 5, 1, INT_MAX);
  settings.hideEmitters = in.flag("hide_emitters", false);
}

}  // namespace rc
