#include "brdf/table_builder.h"

#include "brdf/table_layout.h"
#include "core/error.h"
#include "core/parallel.h"
#include "rc_types.h"

namespace rc {

std::vector<float> buildBrdfTable(const Bsdf& bsdf, int kind, int order, int res, const LobeQuadrature& quad) {
  if (kind != RC_TABLE_ISOTROPIC_1D && kind != RC_TABLE_ANISOTROPIC_2D)
    throw Error("buildBrdfTable: unknown table kind " + std::to_string(kind));
  if (res < 2) throw Error("buildBrdfTable: table resolution " + std::to_string(res) + " < 2");
  const size_t per = 3u * static_cast<size_t>(order) * order;
  const size_t nodes = kind == RC_TABLE_ISOTROPIC_1D ? static_cast<size_t>(res) : static_cast<size_t>(res) * res;
  std::vector<float> table(nodes * per, 0.0f);
  parallelFor(nodes, 1, [&](size_t begin, size_t end) {
    LobeProjection proj;
    for (size_t n = begin; n < end; ++n) {
      const Vec3 wo = kind == RC_TABLE_ISOTROPIC_1D
                          ? isotropicNodeDirection(static_cast<int>(n), res)
                          : anisotropicNodeDirection(static_cast<int>(n % res), static_cast<int>(n / res), res);
      projectLobe(bsdf, wo, order, quad, proj);
      if (kind == RC_TABLE_ISOTROPIC_1D && n == 0) {
        // Node 0 is the normal, where an isotropic lobe is symmetric about z: only m = 0 terms
        // exist; the rest is quadrature noise and would make the lookup at the pole depend on φ_o.
        const int n2 = order * order;
        for (int c = 0; c < 3; ++c)
          for (int l = 0; l < order; ++l)
            for (int m = -l; m <= l; ++m)
              if (m != 0) proj.coeffs[c * n2 + l * (l + 1) + m] = 0.0;
      }
      for (size_t k = 0; k < per; ++k) table[n * per + k] = static_cast<float>(proj.coeffs[k]);
    }
  });
  return table;
}

}  // namespace rc
