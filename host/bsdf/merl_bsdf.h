#pragma once
// The merl BSDF (host/bsdf/merl.cpp) built from tabulated data already in memory: for the
// generator's round trips and for tests that tabulate a reflectance without writing a file.
#include <memory>

#include "bsdf/bsdf.h"
#include "bsdf/merl_data.h"

namespace rc {

std::shared_ptr<Bsdf> makeMerlBsdf(MerlData data);

}  // namespace rc
