#pragma once
// The statistics block printed after every render and the --stats JSON file.
#include <ostream>
#include <string>

#include "render/integrator.h"

namespace rc {

void printStats(const RenderStats& stats, std::ostream& out);
std::string statsToJson(const RenderStats& stats);

}  // namespace rc
