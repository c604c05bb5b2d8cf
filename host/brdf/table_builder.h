#pragma once
// Builds one material's BRDF×cos coefficient table (layout of host/sh/batches.h, BrdfDotBatch):
// every grid node's lobe projected with projectLobe, nodes spread over threads with parallelFor.
#include <vector>

#include "brdf/lobe_projector.h"
#include "bsdf/bsdf.h"

namespace rc {

// kind: RC_TABLE_ISOTROPIC_1D (res = T) or RC_TABLE_ANISOTROPIC_2D (res = S). Returns
// tableFloatCount(kind, order, res) floats, node-major, [node][3][order²].
std::vector<float> buildBrdfTable(const Bsdf& bsdf, int kind, int order, int res, const LobeQuadrature& quad);

}  // namespace rc
