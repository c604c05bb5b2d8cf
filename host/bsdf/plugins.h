#pragma once
// Constructors of the BSDF plugins, one per file, gathered by the factory table (bsdf_factory.cpp).
// Each reads its parameters from `props` (validating them) and takes ownership of `nested`.
#include <vector>

#include "bsdf/bsdf.h"
#include "bsdf/bsdf_textures.h"
#include "core/properties.h"

namespace rc {

using BsdfConstructor = std::shared_ptr<Bsdf> (*)(const Properties& props, const std::vector<BsdfPtr>& nested);
// Plugins that evaluate textured parameters per point (Bsdf::at).
using TexturedBsdfConstructor = std::shared_ptr<Bsdf> (*)(const Properties& props, const std::vector<BsdfPtr>& nested,
                                                          const BsdfTextures& textures);

std::shared_ptr<Bsdf> createDiffuseBsdf(const Properties& props, const std::vector<BsdfPtr>& nested);
std::shared_ptr<Bsdf> createRoughConductorBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                               const BsdfTextures& textures);
std::shared_ptr<Bsdf> createConductorBsdf(const Properties& props, const std::vector<BsdfPtr>& nested);
std::shared_ptr<Bsdf> createPlasticBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                        const BsdfTextures& textures);
std::shared_ptr<Bsdf> createRoughPlasticBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                             const BsdfTextures& textures);
std::shared_ptr<Bsdf> createDielectricBsdf(const Properties& props, const std::vector<BsdfPtr>& nested);
std::shared_ptr<Bsdf> createThinDielectricBsdf(const Properties& props, const std::vector<BsdfPtr>& nested);
std::shared_ptr<Bsdf> createTwoSidedBsdf(const Properties& props, const std::vector<BsdfPtr>& nested);
std::shared_ptr<Bsdf> createBlendBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                      const BsdfTextures& textures);
std::shared_ptr<Bsdf> createMerlBsdf(const Properties& props, const std::vector<BsdfPtr>& nested);
std::shared_ptr<Bsdf> createNullBsdf(const Properties& props, const std::vector<BsdfPtr>& nested);
std::shared_ptr<Bsdf> createRoughDielectricBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                                const BsdfTextures& textures);
std::shared_ptr<Bsdf> createPrincipledBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                           const BsdfTextures& textures);
// The name the loader gives a bumpmap's one texture child (Mitsuba takes it under any name).
constexpr const char* kBumpMapTextureParameter = "bumpmap_height";
std::shared_ptr<Bsdf> createNormalMapBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                          const BsdfTextures& textures);
std::shared_ptr<Bsdf> createBumpMapBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                        const BsdfTextures& textures);
std::shared_ptr<Bsdf> createMaskBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                     const BsdfTextures& textures);
std::shared_ptr<Bsdf> createPolarizedPlasticBsdf(const Properties& props, const std::vector<BsdfPtr>& nested,
                                                 const BsdfTextures& textures);
std::shared_ptr<Bsdf> createPolarizerBsdf(const Properties& props, const std::vector<BsdfPtr>& nested);

}  // namespace rc
