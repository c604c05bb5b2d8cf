// bsdf "polarizer": a linear polarising filter (Mitsuba 3 src/bsdfs/polarizer.cpp), in RGB mode.
//
// | parameter     | type             | default | meaning                                                  |
// |---------------|------------------|---------|----------------------------------------------------------|
// | theta         | float / spectrum | 0       | angle of the transmission axis (degrees); read, no effect |
// | transmittance | rgb / float      | 1       | t: the filter's transmittance                             |
// | polarizing    | boolean          | true    | false: an absorber; the same in RGB mode                  |
//
// Mitsuba's RGB variants carry no polarisation state, so its polarizer is an infinitely thin sheet
// every ray passes straight through with weight t/2 (unpolarised light loses half its power in a
// linear polariser; theta only matters to polarised light): sample() returns wi = −wo as a Dirac
// transmission (BSDFFlags::Null, like the null BSDF), eval and pdf are 0. As there, the crossing is
// a path vertex and shadow rays are blocked by the sheet.
#include "bsdf/bsdf_params.h"
#include "bsdf/pass_through.h"
#include "bsdf/plugins.h"

namespace rc {
namespace {

class PolarizerBsdf final : public Bsdf {
 public:
  explicit PolarizerBsdf(const Color& transmittance) : transmittance_(transmittance) {}

  Color eval(const Vec3&, const Vec3&) const override { return Color(0.0f); }
  float pdf(const Vec3&, const Vec3&) const override { return 0.0f; }
  std::optional<BsdfSample> sample(const Vec3& wo, float, const Vec2&) const override {
    auto s = passThroughSample(wo);
    if (s) s->weight = 0.5f * transmittance_;
    return s;
  }
  uint32_t lobes() const override { return kLobeDelta | kLobeTransmission; }
  Color nullTransmission() const override { return 0.5f * transmittance_; }
  std::string parameterKey() const override { return "polarizer(transmittance=" + hexColor(transmittance_) + ")"; }
  std::string typeName() const override { return "polarizer"; }

 private:
  Color transmittance_;
};

}  // namespace

std::shared_ptr<Bsdf> createPolarizerBsdf(const Properties& props, const std::vector<BsdfPtr>&) {
  // theta and polarizing only change polarised light: read (so they are not "unsupported"), unused.
  if (const Property* theta = props.property("theta")) {
    const bool numeric = theta->type == Property::Type::Float || theta->type == Property::Type::Integer ||
                         theta->type == Property::Type::Rgb;
    if (!numeric) throwParamError(props, "theta", "must be a number (degrees)");
  }
  props.getBool("polarizing", true);
  return std::make_shared<PolarizerBsdf>(readReflectance(props, "transmittance", 1.0f));
}

}  // namespace rc
