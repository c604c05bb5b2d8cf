#include "brdf/material_plan.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>

#include "brdf/order_selection.h"
#include "brdf/table_builder.h"
#include "brdf/table_cache.h"
#include "brdf/table_layout.h"
#include "bsdf/alpha_family.h"
#include "core/error.h"
#include "core/json_writer.h"

namespace rc {

namespace {

std::string hexFloat(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

std::string quadKey(const LobeQuadrature& q) {
  return "quad=" + std::to_string(q.bsdfSamples) + "/" + std::to_string(q.cosineSamples);
}

using Kind = BrdfTableSet::Kind;

Kind classify(const Bsdf& bsdf) {
  const uint32_t lobes = bsdf.lobes();
  if (lobes & (kLobeDelta | kLobeTransmission)) return Kind::Sampled;
  // Parameters textured per point (Bsdf::at): one table per material does not describe it, unless
  // the only one is a roughness (tables over α).
  if (alphaFamilyOf(bsdf) && lobes == kLobeGlossy) return Kind::Glossy;
  if (bsdf.spatiallyVarying()) return Kind::Sampled;
  if (lobes == kLobeDiffuse) return Kind::Diffuse;
  if (lobes & kLobeGlossy) return Kind::Glossy;
  return Kind::Sampled;  // no continuous reflection lobe: nothing to cache
}

void checkOptions(const BrdfTableOptions& opt) {
  if (opt.maxOrder < 1 || opt.maxOrder > kMaxKernelOrder)
    throw Error("brdf tables: max SH order " + std::to_string(opt.maxOrder) + " outside 1.." + std::to_string(kMaxKernelOrder));
  if (opt.orderOverride < 0 || opt.orderOverride > kMaxKernelOrder)
    throw Error("brdf tables: SH order " + std::to_string(opt.orderOverride) + " outside 1.." + std::to_string(kMaxKernelOrder));
  if (opt.diffuseOrder < 1 || opt.diffuseOrder > kMaxKernelOrder)
    throw Error("brdf tables: diffuse SH order " + std::to_string(opt.diffuseOrder) + " outside 1.." + std::to_string(kMaxKernelOrder));
  if (!(opt.tolerance > 0.0 && opt.tolerance < 1.0))
    throw Error("brdf tables: tolerance " + std::to_string(opt.tolerance) + " outside (0, 1)");
  if (opt.isotropicRes < 2 || opt.anisotropicRes < 2 || opt.diffuseRes < 2)
    throw Error("brdf tables: table resolutions must be at least 2");
}

}  // namespace

// The disk cache of plans and tables, or none (disabled, or no cached material).
struct BrdfDiskTables {
  std::unique_ptr<BrdfDiskCache> cache;
  bool forceRebuild = false;
  bool load(const std::string& key, CachedBlob& blob) const { return cache && !forceRebuild && cache->load(key, blob); }
  void store(const std::string& key, const CachedBlob& blob) const {
    if (cache) cache->store(key, blob);
  }
};

namespace {

// The SH order of a glossy material (0: too sharp for the cap) and its worst truncation error per
// order, from the disk cache or selectShOrder. `hit` becomes false when computed.
int glossyOrder(const Bsdf& bsdf, const std::string& base, const BrdfTableOptions& opt, const BrdfDiskTables& disk,
                std::vector<double>& worst, bool& hit) {
  const std::string planKey = base + "\nplan tol=" + hexFloat(opt.tolerance) + " theta=" + hexFloat(opt.planMaxThetaDeg) +
                              " max=" + std::to_string(opt.maxOrder) + " " + quadKey(opt.planQuadrature);
  CachedBlob blob;
  if (disk.load(planKey, blob) && blob.kind == -1 && blob.res == opt.maxOrder &&
      blob.payload.size() == static_cast<size_t>(opt.maxOrder) && blob.order >= 0 && blob.order <= opt.maxOrder) {
    worst.assign(blob.payload.begin(), blob.payload.end());
    return blob.order;
  }
  hit = false;
  const OrderChoice choice = selectShOrder(bsdf, opt.tolerance, opt.maxOrder, opt.planQuadrature, opt.planMaxThetaDeg);
  worst = choice.worstError;
  blob.kind = -1;
  blob.order = choice.order;
  blob.res = opt.maxOrder;
  blob.payload.assign(worst.begin(), worst.end());
  disk.store(planKey, blob);
  return choice.order;
}

// A table's floats, from the disk cache or built. `hit` becomes false when built.
std::vector<float> loadOrBuildTable(const Bsdf& bsdf, const std::string& tableKey, int kind, int order, int res,
                                    const LobeQuadrature& quad, const BrdfDiskTables& disk, bool& hit) {
  CachedBlob blob;
  if (disk.load(tableKey, blob) && blob.kind == kind && blob.order == order && blob.res == res &&
      blob.payload.size() == tableFloatCount(kind, order, res))
    return std::move(blob.payload);
  hit = false;
  blob.kind = kind;
  blob.order = order;
  blob.res = res;
  blob.payload = buildBrdfTable(bsdf, kind, order, res, quad);
  disk.store(tableKey, blob);
  return std::move(blob.payload);
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void BrdfTableSet::build(const std::vector<BsdfPtr>& bsdfs, const BrdfTableOptions& opt) {
  plans_.clear();
  tables_.clear();
  data_.clear();
  cacheDir_.clear();
  checkOptions(opt);
  auto notice = opt.notice ? opt.notice : [](const std::string& m) { std::cerr << m << "\n"; };
  std::vector<Kind> kinds;
  bool anyCached = false;
  for (const BsdfPtr& b : bsdfs) {
    if (!b) throw Error("brdf tables: null BSDF in the scene's list");
    kinds.push_back(classify(*b));
    anyCached = anyCached || kinds.back() != Kind::Sampled || (opt.lobeSplit && b->baseLayer() && !b->spatiallyVarying());
  }
  BrdfDiskTables disk;
  disk.forceRebuild = opt.forceRebuild;
  if (anyCached && opt.useDiskCache) {
    disk.cache = std::make_unique<BrdfDiskCache>(opt.cacheDir, notice);
    if (disk.cache->enabled()) cacheDir_ = disk.cache->directory();
  }
  std::map<std::string, int> tableByKey;  // equal parameter keys share one table
  for (size_t m = 0; m < bsdfs.size(); ++m)
    plans_.push_back(kinds[m] == Kind::Glossy && alphaFamilyOf(*bsdfs[m]) ? planAlphaNodes(*bsdfs[m], opt, disk, tableByKey)
                                                                            : planMaterial(*bsdfs[m], kinds[m], opt, disk, tableByKey));
}

MaterialPlan BrdfTableSet::planMaterial(const Bsdf& bsdf, Kind kind, const BrdfTableOptions& opt,
                                        const BrdfDiskTables& disk, std::map<std::string, int>& tableByKey) {
  const auto start = std::chrono::steady_clock::now();
  MaterialPlan plan;
  plan.name = bsdf.id.empty() ? bsdf.typeName() : bsdf.id;
  plan.technique = Technique::ImportanceSampling;
  // Layers of a BSDF textured per point would need a table per point (classify).
  const Bsdf* layer = opt.lobeSplit && !bsdf.spatiallyVarying() ? bsdf.baseLayer() : nullptr;
  // A layered BSDF whose coat is a delta lobe: only its base can be cached.
  if (kind == Kind::Sampled && layer && !(bsdf.lobes() & kLobeTransmission)) return planLobeSplit(bsdf, opt, disk, tableByKey, start);
  if (kind == Kind::Sampled) return plan;
  const std::string base = "rcache brdf table v" + std::to_string(kBrdfCacheFormatVersion) + "\n" + bsdf.parameterKey();
  bool hit = true;
  int order = 0;
  if (kind == Kind::Diffuse) {
    plan.technique = Technique::IrradianceCache;
    order = opt.diffuseOrder;
  } else if (opt.orderOverride > 0) {
    plan.technique = Technique::RadianceCache;
    order = opt.orderOverride;
  } else {
    std::vector<double> worst;
    order = glossyOrder(bsdf, base, opt, disk, worst, hit);
    if (order == 0 && layer) return planLobeSplit(bsdf, opt, disk, tableByKey, start);  // the coat is too sharp
    if (order == 0) {  // too sharp for the cap
      plan.truncationError = worst.empty() ? 0.0 : worst.back();
      plan.tableCacheHit = hit;
      plan.tableMs = millisecondsSince(start);
      return plan;
    }
    plan.technique = Technique::RadianceCache;
    plan.truncationError = worst[order - 1];
  }
  const bool iso1d = bsdf.isotropic();
  const int res = kind == Kind::Diffuse ? opt.diffuseRes : iso1d ? opt.isotropicRes : opt.anisotropicRes;
  addTable(bsdf, base, order, res, opt, disk, tableByKey, plan, hit);
  plan.tableCacheHit = hit;
  plan.tableMs = millisecondsSince(start);
  return plan;
}

// The base layer of a layered BSDF (diffuse under a coat) is planned like a diffuse material, at
// the irradiance cache's order, but its table is tabulated over ω_o like a glossy one: the coat's
// transmittance into the base depends on θ_o.
MaterialPlan BrdfTableSet::planLobeSplit(const Bsdf& bsdf, const BrdfTableOptions& opt, const BrdfDiskTables& disk,
                                         std::map<std::string, int>& tableByKey,
                                         std::chrono::steady_clock::time_point start) {
  const Bsdf& layer = *bsdf.baseLayer();
  MaterialPlan plan;
  plan.name = bsdf.id.empty() ? bsdf.typeName() : bsdf.id;
  plan.technique = Technique::LobeSplit;
  const std::string base = "rcache brdf table v" + std::to_string(kBrdfCacheFormatVersion) + "\n" + layer.parameterKey();
  bool hit = true;
  addTable(layer, base, opt.diffuseOrder, layer.isotropic() ? opt.isotropicRes : opt.anisotropicRes, opt, disk,
           tableByKey, plan, hit);
  plan.tableCacheHit = hit;
  plan.tableMs = millisecondsSince(start);
  return plan;
}

void BrdfTableSet::addTable(const Bsdf& bsdf, const std::string& base, int order, int res, const BrdfTableOptions& opt,
                            const BrdfDiskTables& disk, std::map<std::string, int>& tableByKey, MaterialPlan& plan,
                            bool& hit) {
  const int tableKind = bsdf.isotropic() ? RC_TABLE_ISOTROPIC_1D : RC_TABLE_ANISOTROPIC_2D;
  const LobeQuadrature& quad = tableKind == RC_TABLE_ANISOTROPIC_2D ? opt.anisotropicQuadrature : opt.tableQuadrature;
  const std::string tableKey = base + "\ntable kind=" + std::to_string(tableKind) + " res=" + std::to_string(res) +
                               " order=" + std::to_string(order) + " " + quadKey(quad);
  plan.shOrder = order;
  plan.tableKind = tableKind;
  if (auto it = tableByKey.find(tableKey); it != tableByKey.end()) {
    plan.tableIndex = it->second;  // same parameters as an earlier material
    return;
  }
  const std::vector<float> payload = loadOrBuildTable(bsdf, tableKey, tableKind, order, res, quad, disk, hit);
  RcBrdfTable t;
  t.kind = tableKind;
  t.order = order;
  t.res = res;
  if (data_.size() + payload.size() > static_cast<size_t>(INT32_MAX))
    throw Error("brdf tables: table data exceeds 2^31 floats");
  t.offset = static_cast<int32_t>(data_.size());
  data_.insert(data_.end(), payload.begin(), payload.end());
  plan.tableIndex = static_cast<int>(tables_.size());
  tables_.push_back(t);
  tableByKey[tableKey] = plan.tableIndex;
}

bool BrdfTableSet::anyLobeSplit() const {
  for (const MaterialPlan& p : plans_)
    if (p.technique == Technique::LobeSplit) return true;
  return false;
}

MaterialPlan BrdfTableSet::planAlphaNodes(const Bsdf& bsdf, const BrdfTableOptions& opt, const BrdfDiskTables& disk,
                                          std::map<std::string, int>& tableByKey) {
  const auto start = std::chrono::steady_clock::now();
  const AlphaFamily& family = *alphaFamilyOf(bsdf);
  const auto [lo, hi] = family.alphaRange();
  const std::vector<float> nodes = alphaNodesOver(lo, hi);
  // The sharpest α needs the highest order: it decides the technique and the order of all nodes.
  MaterialPlan plan = planMaterial(*family.withAlpha(nodes.front()), Kind::Glossy, opt, disk, tableByKey);
  plan.name = bsdf.id.empty() ? bsdf.typeName() : bsdf.id;
  if (plan.tableIndex >= 0) {
    BrdfTableOptions atOrder = opt;
    atOrder.orderOverride = plan.shOrder;
    plan.alphaNodes = nodes;
    plan.alphaTables.push_back(plan.tableIndex);
    for (size_t k = 1; k < nodes.size(); ++k) {
      const MaterialPlan node = planMaterial(*family.withAlpha(nodes[k]), Kind::Glossy, atOrder, disk, tableByKey);
      plan.alphaTables.push_back(node.tableIndex);
      plan.tableCacheHit = plan.tableCacheHit && node.tableCacheHit;
    }
  }
  plan.tableMs = millisecondsSince(start);
  return plan;
}

std::vector<float> alphaNodesOver(float lo, float hi) {
  if (!(lo > 0.0f) || !(hi > lo * 1.0001f)) return {lo > 0.0f ? lo : hi};
  const double ratio = std::log(double(hi) / lo);
  const int n = std::clamp(static_cast<int>(std::ceil(ratio / std::log(std::sqrt(2.0)))) + 1, 2, kMaxAlphaNodes);
  std::vector<float> nodes(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) nodes[static_cast<size_t>(k)] = static_cast<float>(lo * std::exp(ratio * k / (n - 1)));
  nodes.back() = hi;
  return nodes;
}

int MaterialPlan::tableAt(float alpha, float u) const {
  if (alphaNodes.empty()) return tableIndex;
  if (!(alpha > alphaNodes.front())) return alphaTables.front();
  if (!(alpha < alphaNodes.back())) return alphaTables.back();
  const size_t k = static_cast<size_t>(std::upper_bound(alphaNodes.begin(), alphaNodes.end(), alpha) - alphaNodes.begin()) - 1;
  const float t = std::log(alpha / alphaNodes[k]) / std::log(alphaNodes[k + 1] / alphaNodes[k]);
  return u < t ? alphaTables[k + 1] : alphaTables[k];
}

int BrdfTableSet::maxTableOrder() const {
  int n = 0;
  for (const RcBrdfTable& t : tables_) n = std::max(n, t.order);
  return n;
}

void BrdfTableSet::fillBatch(BrdfDotBatch& batch) const {
  batch.tables = tables_;
  batch.tableData = data_;
}

void BrdfTableSet::lookup(int tableIndex, const Vec3& wo, std::vector<double>& out) const {
  if (tableIndex < 0 || tableIndex >= static_cast<int>(tables_.size()))
    throw Error("brdf tables: table index " + std::to_string(tableIndex) + " out of range");
  const RcBrdfTable& t = tables_[tableIndex];
  lookupTable(t, data_.data() + t.offset, wo, out);
}

const char* techniqueName(Technique t) {
  switch (t) {
    case Technique::IrradianceCache: return "irradiance cache";
    case Technique::RadianceCache: return "radiance cache";
    case Technique::ImportanceSampling: return "importance sampling";
    case Technique::LobeSplit: return "lobe split";
    case Technique::None: break;
  }
  return "none";
}

std::string BrdfTableSet::materialsJson() const {
  JsonWriter w;
  w.beginArray();
  for (const MaterialPlan& p : plans_)
    w.beginObject()
        .field("name", p.name)
        .field("technique", techniqueName(p.technique))
        .field("sh_order", p.shOrder)
        .field("table_ms", p.tableMs)
        .field("table_cache_hit", p.tableCacheHit)
        .field("alpha_nodes", static_cast<int>(p.alphaNodes.size()))
        .endObject();
  w.endArray();
  return w.str();
}

double BrdfTableSet::totalMs() const {
  double s = 0;
  for (const MaterialPlan& p : plans_) s += p.tableMs;
  return s;
}

}  // namespace rc
