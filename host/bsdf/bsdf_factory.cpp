#include "bsdf/bsdf_factory.h"

#include <atomic>
#include <cstring>

#include "bsdf/plugins.h"
#include "core/error.h"

namespace rc {
namespace {

struct FactoryEntry {
  const char* type;
  BsdfConstructor create;
  size_t minNested, maxNested;
};

// The factory table: Mitsuba 3 plugin name → constructor and the number of nested BSDFs it takes
// ("merl" is an rcache extension).
const FactoryEntry kFactory[] = {
    {"diffuse", createDiffuseBsdf, 0, 0},
    {"roughconductor", createRoughConductorBsdf, 0, 0},
    {"conductor", createConductorBsdf, 0, 0},
    {"plastic", createPlasticBsdf, 0, 0},
    {"roughplastic", createRoughPlasticBsdf, 0, 0},
    {"dielectric", createDielectricBsdf, 0, 0},
    {"thindielectric", createThinDielectricBsdf, 0, 0},
    {"twosided", createTwoSidedBsdf, 1, 2},
    {"blendbsdf", createBlendBsdf, 2, 2},
    {"merl", createMerlBsdf, 0, 0},
};

const FactoryEntry* findEntry(const std::string& type) {
  for (const FactoryEntry& e : kFactory)
    if (type == e.type) return &e;
  return nullptr;
}

std::atomic<int> gAnonymousCount{0};

}  // namespace

bool isKnownBsdfType(const std::string& type) { return findEntry(type) != nullptr; }

BsdfPtr createBsdf(const Properties& props, const std::vector<BsdfPtr>& nested, const std::string& id) {
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
  std::shared_ptr<Bsdf> bsdf = e->create(props, nested);
  bsdf->id = id.empty() ? props.pluginType + "#" + std::to_string(gAnonymousCount++) : id;
  return bsdf;
}

BsdfPtr createBsdf(const Properties& props, const std::vector<BsdfPtr>& nested) {
  return createBsdf(props, nested, std::string());
}

}  // namespace rc
