#include "bsdf/bsdf_factory.h"

#include <atomic>
#include <cstring>

#include "bsdf/plugins.h"
#include "core/error.h"

namespace rc {
namespace {

struct FactoryEntry {
  const char* type;
  BsdfConstructor create;            // null when the plugin takes textures
  TexturedBsdfConstructor textured;  // null when it takes none
  size_t minNested, maxNested;
  // Evaluated per point (Bsdf::at), space-separated; ":rgb" marks a colour (the others are
  // scalars, Mitsuba's eval_1).
  const char* textureParameters;
};

// The factory table: Mitsuba 3 plugin name → constructor, the number of nested BSDFs it takes and
// the parameters it evaluates per point ("merl" is an rcache extension). Textures on a factor of
// the whole BSDF (bsdf/textured.h) are handled by the loader, not here.
const FactoryEntry kFactory[] = {
    {"diffuse", createDiffuseBsdf, nullptr, 0, 0, ""},
    {"roughconductor", nullptr, createRoughConductorBsdf, 0, 0, "alpha alpha_u alpha_v"},
    {"conductor", createConductorBsdf, nullptr, 0, 0, ""},
    {"plastic", nullptr, createPlasticBsdf, 0, 0, "diffuse_reflectance:rgb specular_reflectance:rgb"},
    {"roughplastic", nullptr, createRoughPlasticBsdf, 0, 0, "diffuse_reflectance:rgb specular_reflectance:rgb"},
    {"dielectric", createDielectricBsdf, nullptr, 0, 0, ""},
    {"roughdielectric", nullptr, createRoughDielectricBsdf, 0, 0, "alpha alpha_u alpha_v"},
    {"thindielectric", createThinDielectricBsdf, nullptr, 0, 0, ""},
    {"twosided", createTwoSidedBsdf, nullptr, 1, 2, ""},
    {"blendbsdf", nullptr, createBlendBsdf, 2, 2, "weight"},
    {"null", createNullBsdf, nullptr, 0, 0, ""},
    {"mask", nullptr, createMaskBsdf, 1, 1, "opacity"},
    {"pplastic", nullptr, createPolarizedPlasticBsdf, 0, 0, "diffuse_reflectance:rgb specular_reflectance:rgb"},
    {"polarizer", createPolarizerBsdf, nullptr, 0, 0, ""},
    {"principled", nullptr, createPrincipledBsdf, 0, 0,
     "base_color:rgb roughness anisotropic metallic spec_trans spec_tint sheen sheen_tint flatness clearcoat "
     "clearcoat_gloss"},
    {"merl", createMerlBsdf, nullptr, 0, 0, ""},
    {"normalmap", nullptr, createNormalMapBsdf, 1, 1, "normalmap:rgb"},
    {"bumpmap", nullptr, createBumpMapBsdf, 1, 1, "bumpmap_height"},
};

const FactoryEntry* findEntry(const std::string& type) {
  for (const FactoryEntry& e : kFactory)
    if (type == e.type) return &e;
  return nullptr;
}

std::atomic<int> gAnonymousCount{0};

}  // namespace

bool isKnownBsdfType(const std::string& type) { return findEntry(type) != nullptr; }

namespace {
// The entry of `parameter` in the type's texture list ("name" or "name:rgb"), "" when absent.
std::string textureParameterEntry(const std::string& type, const std::string& parameter) {
  const FactoryEntry* e = findEntry(type);
  if (!e || parameter.empty()) return "";
  const std::string list = std::string(" ") + e->textureParameters + " ";
  for (const std::string& token : {parameter, parameter + ":rgb"})
    if (list.find(" " + token + " ") != std::string::npos) return token;
  return "";
}
}  // namespace

bool isBsdfTextureParameter(const std::string& type, const std::string& parameter) {
  return !textureParameterEntry(type, parameter).empty();
}

bool isBsdfColorTextureParameter(const std::string& type, const std::string& parameter) {
  const std::string entry = textureParameterEntry(type, parameter);
  return entry.size() > 4 && entry.compare(entry.size() - 4, 4, ":rgb") == 0;
}

BsdfPtr createBsdf(const Properties& props, const std::vector<BsdfPtr>& nested, const std::string& id,
                   const BsdfTextures& textures) {
  const FactoryEntry* e = findEntry(props.pluginType);
  if (!e) {
    std::string known;
    for (const FactoryEntry& k : kFactory) known += std::string(known.empty() ? "" : ", ") + k.type;
    throw Error("<bsdf type=\"" + props.pluginType + "\">: unknown BSDF plugin '" + props.pluginType +
                "' (supported: " + known + ")");
  }
  if (nested.size() < e->minNested || nested.size() > e->maxNested) {
    const std::string expected = e->minNested == e->maxNested
                                     ? std::to_string(e->minNested)
                                     : std::to_string(e->minNested) + " to " + std::to_string(e->maxNested);
    throw Error("<bsdf type=\"" + props.pluginType + "\">: takes " + expected + " nested BSDF(s), got " +
                std::to_string(nested.size()));
  }
  // The integrators perturb the point's frame once, from the material it is shaded with.
  for (const BsdfPtr& b : nested)
    if (b && b->perturbsFrame())
      throw Error("<bsdf type=\"" + props.pluginType + "\">: a nested '" + b->typeName() +
                  "' is not supported (a normalmap or bumpmap must be the shape's outermost BSDF)");
  for (const auto& [name, texture] : textures)
    if (!texture || !isBsdfTextureParameter(props.pluginType, name))
      throw Error("<bsdf type=\"" + props.pluginType + "\">: parameter '" + name + "' cannot be a texture");
  std::shared_ptr<Bsdf> bsdf = e->textured ? e->textured(props, nested, textures) : e->create(props, nested);
  bsdf->id = id.empty() ? props.pluginType + "#" + std::to_string(gAnonymousCount++) : id;
  return bsdf;
}

BsdfPtr createBsdf(const Properties& props, const std::vector<BsdfPtr>& nested, const std::string& id) {
  return createBsdf(props, nested, id, BsdfTextures());
}

BsdfPtr createBsdf(const Properties& props, const std::vector<BsdfPtr>& nested) {
  return createBsdf(props, nested, std::string());
}

}  // namespace rc
