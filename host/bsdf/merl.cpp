// bsdf "merl" (rcache extension, not a Mitsuba 3 plugin): a measured isotropic BRDF tabulated in
// the MERL binary format (bsdf/merl_data.h), e.g. a file of the MERL/MIT database.
//
// | parameter      | type    | default | meaning                                                    |
// |----------------|---------|---------|------------------------------------------------------------|
// | filename       | string  | —       | the .binary file, relative to the scene file like meshes   |
// | clamp_negative | boolean | false   | read negative entries as 0 (else they are an error)        |
//
// One-sided reflection: f(ω_o, ω_i) is the table at the pair's half/difference angles
// (Rusinkiewicz), trilinear between the nodes. The reference reader takes the nearest node below
// (it truncates the index); trilinear has O(h²) instead of O(h) discretisation error, which matters
// where the table is coarse relative to the lobe (a 1° step in θ_d across a Fresnel rise, θ_h
// steps of up to 2° at the rim) and keeps the lookup continuous, so highlights show no bands.
// At the nodes both agree. Reciprocity is exact: the table stores φ_d ∈ [0, π) and the swap of
// ω_i and ω_o maps φ_d to φ_d + π, which folds onto the same entry (the lookup wraps φ_d
// periodically across π, so the interpolation is symmetric too).
// Sampling: with probability 0.9 the tabulated half-vector importance function built from the
// data (bsdf/merl_sampler.h), else the cosine-weighted hemisphere, which keeps the density
// positive wherever the table's cells missed some of the lobe; pdf() is that mixture.
// parameterKey() names the file's content hash, so cached coefficient tables follow the data, not
// the file name.
#include <cstdio>

#include "bsdf/bsdf_params.h"
#include "bsdf/merl_bsdf.h"
#include "bsdf/merl_sampler.h"
#include "bsdf/plugins.h"
#include "bsdf/warp.h"
#include "core/user_cache.h"

namespace rc {
namespace {

constexpr float kCosineFraction = 0.1f;

class MerlBsdf final : public Bsdf {
 public:
  explicit MerlBsdf(MerlData data)
      : data_(std::move(data)),
        sampler_([this](const Vec3& wo, const Vec3& wi) {
          const Color f = data_.lookup(halfDiffAngles(wi, wo));
          return (double(f.r) + f.g + f.b) * wi.z;
        }),
        key_("merl(dims=" + std::to_string(data_.thetaHalfRes) + "x" + std::to_string(data_.thetaDiffRes) + "x" +
             std::to_string(data_.phiDiffRes) + ";content=" + hex64(data_.contentHash) +
             ";values=" + hex64(fnv1a64(data_.values.data(), data_.values.size() * sizeof(float))) + ")") {}

  Color eval(const Vec3& wo, const Vec3& wi) const override {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return Color(0.0f);
    return data_.lookup(halfDiffAngles(wi, wo)) * wi.z;
  }

  float pdf(const Vec3& wo, const Vec3& wi) const override {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
    return (1.0f - kCosineFraction) * sampler_.pdf(wo, wi) + kCosineFraction * squareToCosineHemispherePdf(wi);
  }

  std::optional<BsdfSample> sample(const Vec3& wo, float u1, const Vec2& u2) const override {
    if (!(wo.z > 0.0f)) return std::nullopt;
    Vec3 wi;
    if (u1 < kCosineFraction) {
      wi = squareToCosineHemisphere(u2);
    } else {
      const float half = (u1 - kCosineFraction) / (1.0f - kCosineFraction);
      const auto w = sampler_.sample(wo, half >= 0.5f, u2);
      if (!w) return std::nullopt;
      wi = *w;
    }
    BsdfSample s;
    s.wi = wi;
    s.pdf = pdf(wo, wi);
    if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) return std::nullopt;
    s.weight = eval(wo, wi) / s.pdf;
    if (!isFinite(s.weight)) return std::nullopt;
    s.lobe = kLobeGlossy;
    return s;
  }

  // Treated as glossy: the data may hold any lobe, so rcache chooses its order from the projection.
  // glossyAlpha() keeps the default (no microfacet width is known for measured data).
  uint32_t lobes() const override { return kLobeGlossy; }
  std::string parameterKey() const override { return key_; }
  std::string typeName() const override { return "merl"; }

 private:
  MerlData data_;
  MerlSampler sampler_;
  std::string key_;  // the values' hash covers clamp_negative, the content hash names the file's bytes
};

}  // namespace

std::shared_ptr<Bsdf> makeMerlBsdf(MerlData data) { return std::make_shared<MerlBsdf>(std::move(data)); }

std::shared_ptr<Bsdf> createMerlBsdf(const Properties& props, const std::vector<BsdfPtr>&) {
  const std::string filename = props.getString("filename", "");
  if (filename.empty()) throwParamError(props, "filename", "missing (the MERL .binary file to read)");
  const bool clampNegative = props.getBool("clamp_negative", false);
  return makeMerlBsdf(readMerlFile(filename, clampNegative));
}

}  // namespace rc
