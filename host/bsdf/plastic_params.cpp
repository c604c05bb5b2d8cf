#include "bsdf/plastic_params.h"

#include "bsdf/bsdf_params.h"
#include "bsdf/rough_textures.h"

namespace rc {

namespace {
float meanOf(const Color& c) { return (c.r + c.g + c.b) / 3.0f; }
}  // namespace

float PlasticParams::specularSamplingWeight() const {
  const float dMean = meanOf(diffuse), sMean = meanOf(specular);
  return sMean / (dMean + sMean);
}

PlasticParams readPlasticParams(const Properties& props, const BsdfTextures& textures) {
  PlasticParams p;
  p.diffuse = readReflectance(props, "diffuse_reflectance", 0.5f);
  p.specular = readReflectance(props, "specular_reflectance", 1.0f);
  p.eta = readIor(props, "int_ior", "polypropylene") / readIor(props, "ext_ior", "air");
  p.nonlinear = props.getBool("nonlinear", false);
  if (meanOf(p.diffuse) + meanOf(p.specular) <= 0.0f)
    throwParamError(props, "diffuse_reflectance", "diffuse and specular reflectance are both zero");
  p.diffuseTexture = textureOf(textures, "diffuse_reflectance");
  p.specularTexture = textureOf(textures, "specular_reflectance");
  return p;
}

}  // namespace rc
