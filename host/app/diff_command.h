#pragma once
#include <ostream>

#include "app/cli_args.h"

namespace rc {
// `rcache diff TEST REFERENCE`: prints RMSE, relMSE, max abs error (or one JSON object with
// --json); --heatmap writes per-pixel relative error as a false-colour PNG. Exit 0.
int runDiff(const DiffArgs& args, std::ostream& out);
}  // namespace rc
