#include "brdf/lobe_projector.h"

#include <cmath>

#include "core/error.h"
#include "sh/sh_basis.h"

namespace rc {

namespace {

// Radical inverse in base 2 (van der Corput) and base 3: with i/N they form a 3-D Hammersley set,
// whose 2-D projections are all well stratified.
double radicalInverse2(uint32_t i) {
  i = (i << 16u) | (i >> 16u);
  i = ((i & 0x55555555u) << 1u) | ((i & 0xAAAAAAAAu) >> 1u);
  i = ((i & 0x33333333u) << 2u) | ((i & 0xCCCCCCCCu) >> 2u);
  i = ((i & 0x0F0F0F0Fu) << 4u) | ((i & 0xF0F0F0F0u) >> 4u);
  i = ((i & 0x00FF00FFu) << 8u) | ((i & 0xFF00FF00u) >> 8u);
  return static_cast<double>(i) * (1.0 / 4294967296.0);
}

double radicalInverse3(uint32_t i) {
  double inv = 1.0 / 3.0, f = inv, r = 0.0;
  while (i > 0) {
    r += f * static_cast<double>(i % 3u);
    i /= 3u;
    f *= inv;
  }
  return r;
}

float toUnitFloat(double u) {  // [0,1) in float, never rounding up to 1
  const float f = static_cast<float>(u);
  return f < 1.0f ? f : 0.99999994f;
}

}  // namespace

void projectLobe(const Bsdf& bsdf, const Vec3& wo, int order, const LobeQuadrature& quad,
                 LobeProjection& out) {
  if (order < 1 || order > 20) throw Error("projectLobe: SH order " + std::to_string(order) + " outside 1..20");
  if (quad.bsdfSamples < 0 || quad.cosineSamples < 0 || quad.bsdfSamples + quad.cosineSamples == 0)
    throw Error("projectLobe: quadrature needs at least one sample");
  const int n2 = order * order;
  out.coeffs.assign(3 * static_cast<size_t>(n2), 0.0);
  out.energy[0] = out.energy[1] = out.energy[2] = 0.0;
  if (!(wo.z > 0.0f)) return;  // the lobe is defined for ω_o above the horizon only

  const double nb = quad.bsdfSamples, nc = quad.cosineSamples;
  std::vector<double> y(static_cast<size_t>(n2));
  double* acc = out.coeffs.data();

  auto accumulate = [&](const Vec3& wi) {
    if (!(wi.z > 0.0f)) return;  // zero below the horizon, by definition of the table
    const Color g = bsdf.eval(wo, wi);
    if (!(g.r > 0.0f || g.g > 0.0f || g.b > 0.0f) || !isFinite(g)) return;
    const double pb = nb > 0 ? static_cast<double>(bsdf.pdf(wo, wi)) : 0.0;
    const double pc = static_cast<double>(wi.z) * (1.0 / kPiD);
    const double denom = nb * pb + nc * pc;
    if (!(denom > 0.0)) return;  // unreachable by either strategy: contributes nothing to the estimate
    const double w = 1.0 / denom;
    const double gc[3] = {g.r * w, g.g * w, g.b * w};
    for (int c = 0; c < 3; ++c) out.energy[c] += static_cast<double>(g[c]) * g[c] * w;
    // Normalise in double: the float direction from the sampler is unit only to ~1e-7.
    const double len = std::sqrt(double(wi.x) * wi.x + double(wi.y) * wi.y + double(wi.z) * wi.z);
    sh::evalBasis(order, wi.x / len, wi.y / len, wi.z / len, y.data());
    for (int c = 0; c < 3; ++c) {
      if (gc[c] == 0.0) continue;
      double* a = acc + static_cast<size_t>(c) * n2;
      for (int i = 0; i < n2; ++i) a[i] += gc[c] * y[i];
    }
  };

  for (int s = 0; s < quad.bsdfSamples; ++s) {
    const double u0 = (s + 0.5) / nb;
    const Vec2 u2(toUnitFloat(radicalInverse2(static_cast<uint32_t>(s))),
                  toUnitFloat(radicalInverse3(static_cast<uint32_t>(s))));
    const auto bs = bsdf.sample(wo, toUnitFloat(u0), u2);
    if (!bs || bs->pdf <= 0.0f) continue;  // failed or delta sample: counted (N_b fixed), adds 0
    accumulate(bs->wi);
  }
  // Cosine-weighted hemisphere on a 2-D Hammersley set shifted by a fixed offset, so that it does
  // not share strata boundaries with the BSDF set.
  for (int s = 0; s < quad.cosineSamples; ++s) {
    const double u = std::fmod((s + 0.5) / nc + 0.3183098861837907, 1.0);
    const double v = std::fmod(radicalInverse2(static_cast<uint32_t>(s)) + 0.6180339887498949, 1.0);
    const double r = std::sqrt(u), phi = 2.0 * kPiD * v;
    const double z = std::sqrt(std::fmax(0.0, 1.0 - u));
    accumulate(Vec3(static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)),
                    static_cast<float>(z)));
  }
}

}  // namespace rc
