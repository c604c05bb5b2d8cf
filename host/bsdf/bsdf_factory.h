#pragma once
// Factory table (name → constructor) for BSDFs. The parser hands over the typed parameters and
// the nested BSDFs (twosided: 1, blendbsdf: 2); the factory reads the parameters it supports
// (Properties tracks use, so the parser can reject unknown ones) and validates values
// (e.g. alpha ≤ 0, eta NaN → rc::Error naming the parameter).
#include <string>
#include <vector>

#include "bsdf/bsdf.h"
#include "bsdf/bsdf_textures.h"
#include "core/properties.h"

namespace rc {

bool isKnownBsdfType(const std::string& type);
BsdfPtr createBsdf(const Properties& props, const std::vector<BsdfPtr>& nested);
// Same, setting Bsdf::id (the returned BSDF is const): `id` when non-empty, else "<type>#<n>".
BsdfPtr createBsdf(const Properties& props, const std::vector<BsdfPtr>& nested, const std::string& id);
// Same, with textures on the parameters the plugin evaluates per point (isBsdfTextureParameter);
// each such parameter is also in `props`, at the texture's mean.
BsdfPtr createBsdf(const Properties& props, const std::vector<BsdfPtr>& nested, const std::string& id,
                   const BsdfTextures& textures);
// True when plugin `type` evaluates a texture on `parameter` per point (Bsdf::at).
bool isBsdfTextureParameter(const std::string& type, const std::string& parameter);
// Of those, the colour ones (the others are scalars: the loader's stand-in is the mean's luminance).
bool isBsdfColorTextureParameter(const std::string& type, const std::string& parameter);

}  // namespace rc
