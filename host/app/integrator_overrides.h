#pragma once
// -D name=value for the integrator's own parameters, after the scene is loaded. Mitsuba's -D only
// substitutes $name; rcache also lets it override a parameter the file writes literally. The
// shared path parameters (max_depth, rr_depth, hide_emitters) are typed at load, so an override
// must be parsed and checked here, and any option the chosen integrator would ignore is refused:
// nothing given on the command line is silently dropped.
#include <string>

#include "app/cli_args.h"
#include "scene/scene.h"

namespace rc {

// integrator: "rcache" or "path" (resolved). Throws rc::Error naming the option.
void applyIntegratorOptions(const RenderArgs& args, const std::string& integrator, IntegratorSettings& settings);

}  // namespace rc
