#pragma once
// One term of a layered BSDF's sum (Bsdf::baseLayer/coatLayer: a coat over a diffuse base) as a
// BSDF of its own. `Whole` (plastic, roughplastic) defines the terms:
//   Color layerEval(bool coat, wo, wi)   — the term's f·cosθi, for wo.z > 0 and wi.z > 0
//   float layerPdf(bool coat, wo, wi)    — the density of layerSample, same domain
//   std::optional<BsdfSample> layerSample(bool coat, wo, u2) — for wo.z > 0
// and the layer forwards to it; the layer must not outlive the whole.
#include <memory>
#include <string>

#include "bsdf/bsdf.h"

namespace rc {

template <class Whole>
class BsdfLayer final : public Bsdf {
 public:
  BsdfLayer(const Whole& whole, bool coat, uint32_t lobes) : whole_(whole), coat_(coat), lobes_(lobes) {}
  Color eval(const Vec3& wo, const Vec3& wi) const override {
    return wo.z > 0.0f && wi.z > 0.0f ? whole_.layerEval(coat_, wo, wi) : Color(0.0f);
  }
  float pdf(const Vec3& wo, const Vec3& wi) const override {
    return wo.z > 0.0f && wi.z > 0.0f ? whole_.layerPdf(coat_, wo, wi) : 0.0f;
  }
  std::optional<BsdfSample> sample(const Vec3& wo, float /*u1*/, const Vec2& u2) const override {
    if (!(wo.z > 0.0f)) return std::nullopt;
    return whole_.layerSample(coat_, wo, u2);
  }
  uint32_t lobes() const override { return lobes_; }
  float glossyAlpha() const override { return coat_ ? whole_.glossyAlpha() : INFINITY; }
  std::string parameterKey() const override { return (coat_ ? "coat of " : "base of ") + whole_.parameterKey(); }
  std::string typeName() const override { return whole_.typeName() + (coat_ ? " coat" : " base"); }

 private:
  const Whole& whole_;
  bool coat_;
  uint32_t lobes_;
};

// The two layers of a `Whole`, made by bind(whole, coatLobes) for that object. Copying a Whole
// (Bsdf::at's per-point copies) copies no layers: they would refer to the original, so the copy
// binds its own.
template <class Whole>
struct BsdfLayers {
  BsdfLayers() = default;
  BsdfLayers(const BsdfLayers&) {}
  BsdfLayers& operator=(const BsdfLayers&) { return *this; }
  void bind(const Whole& whole, uint32_t coatLobes) {
    base = std::make_unique<BsdfLayer<Whole>>(whole, false, kLobeDiffuse);
    coat = std::make_unique<BsdfLayer<Whole>>(whole, true, coatLobes);
  }
  std::unique_ptr<BsdfLayer<Whole>> base, coat;
};

}  // namespace rc
