// bsdf "null": an invisible surface (Mitsuba 3 src/bsdfs/null.cpp). No parameters.
//
// Every ray passes through unchanged: sample() returns wi = −wo with weight 1 as a Dirac
// transmission (Mitsuba's BSDFFlags::Null, which counts among its Delta flags), eval and pdf are
// 0, so the surface is never light-sampled or shaded. As in Mitsuba's path integrator the crossing
// is a path vertex (it counts toward max_depth) and shadow rays are blocked by the surface.
#include "bsdf/pass_through.h"
#include "bsdf/plugins.h"

namespace rc {
namespace {

class NullBsdf final : public Bsdf {
 public:
  Color eval(const Vec3&, const Vec3&) const override { return Color(0.0f); }
  float pdf(const Vec3&, const Vec3&) const override { return 0.0f; }
  std::optional<BsdfSample> sample(const Vec3& wo, float, const Vec2&) const override { return passThroughSample(wo); }
  uint32_t lobes() const override { return kLobeDelta | kLobeTransmission; }
  Color nullTransmission() const override { return Color(1.0f); }
  std::string parameterKey() const override { return "null()"; }
  std::string typeName() const override { return "null"; }
};

}  // namespace

std::shared_ptr<Bsdf> createNullBsdf(const Properties&, const std::vector<BsdfPtr>&) {
  return std::make_shared<NullBsdf>();
}

}  // namespace rc
