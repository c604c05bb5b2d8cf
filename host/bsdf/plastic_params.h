#pragma once
// What `plastic` and `roughplastic` read alike, with Mitsuba's defaults: the base's and the coat's
// reflectances (constant or textured), η = int_ior / ext_ior (polypropylene / air) and `nonlinear`.
#include "bsdf/bsdf_textures.h"
#include "core/math.h"
#include "core/properties.h"

namespace rc {

struct PlasticParams {
  Color diffuse{0.5f}, specular{1.0f};
  float eta = 1.0f;
  bool nonlinear = false;
  TexturePtr diffuseTexture, specularTexture;
  // The coat's share of the lobe choice, from the mean reflectances (Mitsuba's m_specular_sampling_weight).
  float specularSamplingWeight() const;
};

// Throws the parameter error of bsdf_params.h when both reflectances are zero.
PlasticParams readPlasticParams(const Properties& props, const BsdfTextures& textures);

}  // namespace rc
