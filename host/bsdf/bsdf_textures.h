#pragma once
// Textures on BSDF parameters, by parameter name, handed from the loader to the factory for the
// parameters a plugin evaluates per point (Bsdf::at). The loader also sets each such parameter in
// the Properties to the texture's mean, so validation, defaults and use-tracking see a value.
#include <map>
#include <string>

#include "texture/texture.h"

namespace rc {

using BsdfTextures = std::map<std::string, TexturePtr>;

}  // namespace rc
