#include "bsdf/conductor_fresnel.h"

#include "bsdf/bsdf_params.h"
#include "bsdf/conductor_presets.h"

namespace rc {

static Color readFiniteNonNegative(const Properties& props, const std::string& name, float fallback) {
  const Color c = props.getColor(name, Color(fallback));
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(c[i]) || c[i] < 0.0f)
      throwParamError(props, name, "components must be finite and non-negative (NaN or negative given)");
  return c;
}

ConductorFresnel readConductorFresnel(const Properties& props) {
  ConductorFresnel f;
  f.specularReflectance = readReflectance(props, "specular_reflectance", 1.0f);
  const std::string material = props.getString("material", "none");
  if (material != "none") {
    if (props.has("eta") || props.has("k"))
      throwParamError(props, "material", "give either 'eta'/'k' or 'material', not both");
    if (!lookupConductorPreset(material, &f.eta, &f.k))
      throwParamError(props, "material", "unknown conductor material '" + material + "' (known: none, " +
                                              conductorPresetNames() + ")");
    return f;
  }
  f.eta = readFiniteNonNegative(props, "eta", 0.0f);
  f.k = readFiniteNonNegative(props, "k", 1.0f);
  return f;
}

std::string ConductorFresnel::key() const {
  return "eta=" + hexColor(eta) + ";k=" + hexColor(k) + ";specular_reflectance=" + hexColor(specularReflectance);
}

}  // namespace rc
