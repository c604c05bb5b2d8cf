#include "brdf/order_selection.h"

#include <algorithm>
#include <cmath>

#include "brdf/table_layout.h"
#include "core/error.h"
#include "core/parallel.h"

namespace rc {

namespace {

std::vector<Vec3> planningDirections(bool isotropic, double maxThetaDeg) {
  const double xmax = std::tan(std::clamp(maxThetaDeg, 0.0, 90.0) * kPiD / 360.0);  // parabolic radius
  std::vector<Vec3> dirs;
  if (isotropic) {
    for (int t = 0; t <= 6; ++t) {
      const double x = xmax * t / 6.0, d = 1 + x * x;
      const double z = std::max<double>((1 - x * x) / d, kGrazingCos);
      dirs.push_back(Vec3(float(std::sqrt(1 - z * z)), 0.0f, float(z)));
    }
  } else {
    dirs.push_back(Vec3(0, 0, 1));
    for (int r = 1; r <= 4; ++r)
      for (int a = 0; a < 8; ++a) {
        const double px = xmax * 0.25 * r * std::cos(a * kPiD / 4), py = xmax * 0.25 * r * std::sin(a * kPiD / 4);
        const double r2 = px * px + py * py, d = 1 + r2;
        const double z = std::max<double>((1 - r2) / d, kGrazingCos);
        const double s = std::sqrt(1 - z * z), rxy = std::sqrt(px * px + py * py);
        dirs.push_back(Vec3(float(s * px / rxy), float(s * py / rxy), float(z)));
      }
  }
  return dirs;
}

}  // namespace

OrderChoice selectShOrder(const Bsdf& bsdf, double tolerance, int maxOrder, const LobeQuadrature& quad,
                          double maxThetaDeg) {
  if (maxOrder < 1 || maxOrder > 20) throw Error("selectShOrder: max order " + std::to_string(maxOrder) + " outside 1..20");
  const std::vector<Vec3> dirs = planningDirections(bsdf.isotropic(), maxThetaDeg);
  const int n2 = maxOrder * maxOrder;
  // Per direction and channel: band energy cumulated over bands, and total energy.
  std::vector<std::vector<double>> cumulative(dirs.size() * 3, std::vector<double>(maxOrder, 0.0));
  std::vector<double> total(dirs.size() * 3, 0.0);
  parallelFor(dirs.size(), 1, [&](size_t begin, size_t end) {
    LobeProjection proj;
    for (size_t d = begin; d < end; ++d) {
      projectLobe(bsdf, dirs[d], maxOrder, quad, proj);
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (int l = 0; l < maxOrder; ++l) {
          for (int i = l * l; i < (l + 1) * (l + 1); ++i) sum += proj.coeffs[c * n2 + i] * proj.coeffs[c * n2 + i];
          cumulative[d * 3 + c][l] = sum;
        }
        total[d * 3 + c] = proj.energy[c];
      }
    }
  });
  const double largest = *std::max_element(total.begin(), total.end());
  OrderChoice choice;
  choice.worstError.assign(maxOrder, 0.0);
  if (!(largest > 0.0)) {  // a black lobe: any order represents it exactly
    choice.order = 1;
    return choice;
  }
  for (size_t k = 0; k < total.size(); ++k) {
    if (total[k] < 1e-6 * largest) continue;
    for (int l = 0; l < maxOrder; ++l) {
      // Quadrature noise can push the projected energy a hair above the estimated norm: clamp at 0.
      const double e = std::sqrt(std::max(0.0, 1.0 - cumulative[k][l] / total[k]));
      choice.worstError[l] = std::max(choice.worstError[l], e);
    }
  }
  for (int n = 1; n <= maxOrder; ++n)
    if (choice.worstError[n - 1] <= tolerance) {
      choice.order = n;
      break;
    }
  return choice;
}

}  // namespace rc
