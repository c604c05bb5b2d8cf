#pragma once
// A BSDF whose value is scaled by a texture at the shading point (Bsdf::tint): the loader builds
// diffuse `reflectance` and conductor/roughconductor `specular_reflectance` textures as the BSDF
// with that parameter 1, wrapped here.
#include "bsdf/bsdf.h"
#include "texture/texture.h"

namespace rc {

BsdfPtr makeTexturedBsdf(BsdfPtr unit, TexturePtr factor);

// `tinted` with its factor at uv applied inside eval and sample (tint() then 1): for wrappers whose
// other parts (a mask's pass-through) the factor must not scale.
BsdfPtr bakeTint(BsdfPtr tinted, const TexturePoint& uv);

// The parameters whose texture is a factor on the whole BSDF of `bsdfType` (empty: none).
bool isBsdfFactorParameter(const std::string& bsdfType, const std::string& parameter);

}  // namespace rc
