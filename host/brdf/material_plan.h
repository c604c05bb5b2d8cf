#pragma once
// Per-material technique, SH order and BRDF×cos coefficient table (ARCHITECTURE.md §Pipeline, §Kernels
//). For every BSDF of a scene:
//   delta lobes or transmission        → "importance sampling" (no table)
//   textured per point (Bsdf::at)      → "importance sampling" (no table), except:
//     only an isotropic roughness      → tables over α (bsdf/alpha_family.h): the technique and
//     texture                            order of the sharpest α the texture takes; tables at up to
//                                        kMaxAlphaNodes α spaced by ≤ √2 over its range, all at that
//                                        order, one picked per point (MaterialPlan::tableAt)
//   diffuse only                       → "irradiance cache": order-3 table of the clamped-cosine
//                                        lobe (same table machinery as glossy, one cache)
//   glossy                             → "radiance cache" at the smallest order whose worst
//                                        relative L2 truncation error ≤ tolerance (capped), or
//                                        "importance sampling" when even the cap is too coarse.
//   a layered BSDF (Bsdf::baseLayer/coatLayer) that the rules above would importance-sample as a
//   whole (a sharp or delta coat)   → "lobe split": the base layer's order-3 table; its light
//                                        comes from the records, the coat is sampled.
// Tables follow the BrdfDotBatch layout (host/sh/batches.h): 1-D over the parabolic radius for
// isotropic BSDFs, 2-D parabolic for anisotropic ones. Tables and order choices are cached on
// disk (brdf/table_cache.h). No cached material in the scene → nothing is built.
#include <chrono>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "brdf/lobe_projector.h"
#include "bsdf/bsdf.h"
#include "rc_types.h"
#include "sh/batches.h"

namespace rc {

// How a material's indirect light is estimated; shared by the plan and the cache engine (which
// uses None for points that get no indirect light: inactive, or the back of a one-sided BSDF).
// LobeSplit: the base layer's reflected light from records (its table), the coat's by BSDF and
// light sampling; the two estimates add up to the whole material's (Bsdf::baseLayer).
enum class Technique { None, IrradianceCache, RadianceCache, ImportanceSampling, LobeSplit };

// Whether points of the technique look their light up in records (LobeSplit: the base's part).
inline bool isCached(Technique t) {
  return t == Technique::IrradianceCache || t == Technique::RadianceCache || t == Technique::LobeSplit;
}
// "irradiance cache", "radiance cache", "importance sampling", "lobe split" (statistics), "none".
const char* techniqueName(Technique t);

struct MaterialPlan {
  std::string name;          // Bsdf::id
  Technique technique = Technique::ImportanceSampling;
  int shOrder = 0;           // table order (0 without a table)
  double tableMs = 0.0;      // time to plan + build or load this material's table
  bool tableCacheHit = false;  // table (and order choice) loaded from the disk cache
  int tableIndex = -1;       // index into BrdfTableSet::tables(), -1 without a table
  double truncationError = 0.0;  // worst relative L2 truncation error at shOrder (glossy; 0 if overridden)
  int tableKind = -1;        // RC_TABLE_ISOTROPIC_1D / RC_TABLE_ANISOTROPIC_2D, -1 without a table
  // A material tabulated over α: its nodes (ascending) and each one's table; empty otherwise.
  std::vector<float> alphaNodes;
  std::vector<int> alphaTables;
  // The table of a point of roughness α: one of the two nodes around α, the upper one with
  // probability t (u ∈ [0, 1) uniform), t = α's position between them in log α, so that the
  // expected coefficients are those interpolated in log α; α outside the nodes takes the nearest end.
  // tableIndex when the material has no α nodes.
  int tableAt(float alpha, float u) const;
};

constexpr int kMaxAlphaNodes = 8;
// Nodes over [lo, hi]: geometric, ratio ≤ √2 between neighbours while kMaxAlphaNodes allow.
std::vector<float> alphaNodesOver(float lo, float hi);

struct BrdfTableOptions {
  int orderOverride = 0;       // > 0: every glossy material is radiance-cached at this order
  bool lobeSplit = true;       // false: layered BSDFs are planned whole (no "lobe split")
  // Order choice (brdf/order_selection.h): relative L2 truncation error allowed, worst over view
  // directions with θ_o ≤ planMaxThetaDeg. 10% of the norm = 1% of the lobe's energy outside the band.
  double tolerance = 0.10;
  double planMaxThetaDeg = 60.0;
  int maxOrder = 16;           // cap (kernels support 1..16)
  int diffuseOrder = 3;        // irradiance-cache materials
  int isotropicRes = 64;       // T of 1-D tables
  int anisotropicRes = 32;     // S of 2-D tables
  // A diffuse-only lobe does not depend on ω_o: two nodes represent it exactly.
  int diffuseRes = 2;
  LobeQuadrature tableQuadrature;                 // per node of 1-D tables
  // Per node of 2-D tables: they have ~16× the nodes of a 1-D table, so half the samples keep an
  // anisotropic material near the 1 s budget (S = 32, order 10: ~1 s on 2 cores); the QMC error
  // grows from ~0.3% to ~0.6% of the lobe norm (measured, GGX α ≤ 0.3).
  LobeQuadrature anisotropicQuadrature{1536, 512};
  LobeQuadrature planQuadrature;                  // per planning direction (order maxOrder)
  bool useDiskCache = true;
  std::string cacheDir;        // "" → $RC_CACHE_DIR, $XDG_CACHE_HOME/rcache, ~/.cache/rcache
  bool forceRebuild = false;   // ignore existing files (and overwrite them)
  // One-line notices (cache problems). Empty → written to stderr.
  std::function<void(const std::string&)> notice;
};

struct BrdfDiskTables;  // the disk cache of plans and tables (material_plan.cpp)

class BrdfTableSet {
 public:
  BrdfTableSet() = default;
  // Plans every BSDF (index i of `bsdfs` ↔ plans()[i]) and builds/loads the tables it needs.
  void build(const std::vector<BsdfPtr>& bsdfs, const BrdfTableOptions& options = {});

  const std::vector<MaterialPlan>& plans() const { return plans_; }
  const std::vector<RcBrdfTable>& tables() const { return tables_; }
  const std::vector<float>& data() const { return data_; }  // flat storage, RcBrdfTable::offset
  int maxTableOrder() const;  // 0 when no table
  bool anyLobeSplit() const;   // some material's plan is Technique::LobeSplit

  // Copies tables and data into a batch (material ids of the batch are table indices).
  void fillBatch(BrdfDotBatch& batch) const;
  // F(ω_o) of table `tableIndex` as [3][order²] doubles (CPU lookup, brdf/table_layout.h).
  void lookup(int tableIndex, const Vec3& wo, std::vector<double>& out) const;

  // [{"name":..,"technique":..,"sh_order":..,"table_ms":..,"table_cache_hit":..}, ...]
  std::string materialsJson() const;
  double totalMs() const;
  std::string cacheDirectory() const { return cacheDir_; }  // "" when the disk cache was not used

  // What a material needs: sampling only, an irradiance (diffuse) or a radiance (glossy) cache.
  enum class Kind { Sampled, Diffuse, Glossy };

 private:
  // One material's plan, adding its table unless an equal one (tableByKey) exists.
  MaterialPlan planMaterial(const Bsdf& bsdf, Kind kind, const BrdfTableOptions& opt, const BrdfDiskTables& disk,
                            std::map<std::string, int>& tableByKey);
  // The plan of a material tabulated over α (planMaterial per node).
  MaterialPlan planAlphaNodes(const Bsdf& bsdf, const BrdfTableOptions& opt, const BrdfDiskTables& disk,
                              std::map<std::string, int>& tableByKey);
  // A layered BSDF: technique LobeSplit with its base layer's table.
  MaterialPlan planLobeSplit(const Bsdf& bsdf, const BrdfTableOptions& opt, const BrdfDiskTables& disk,
                             std::map<std::string, int>& tableByKey, std::chrono::steady_clock::time_point start);
  // The table of `bsdf` at `order` into `plan` (shOrder, tableKind, tableIndex), shared with an
  // earlier material of equal key; `hit` becomes false when built.
  void addTable(const Bsdf& bsdf, const std::string& base, int order, int res, const BrdfTableOptions& opt,
                const BrdfDiskTables& disk, std::map<std::string, int>& tableByKey, MaterialPlan& plan, bool& hit);
  std::vector<MaterialPlan> plans_;
  std::vector<RcBrdfTable> tables_;
  std::vector<float> data_;
  std::string cacheDir_;
};

}  // namespace rc
