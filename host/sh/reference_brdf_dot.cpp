// Scalar reference of brdf_dot (batches.h): BRDF×cos coefficient lookup at ω_o, dot with Λ(p).
//  1-D isotropic table: linear in the parabolic radius x = tan(θ_o/2) = √(x²+y²)/(1+z), then the
//  looked-up vector (tabulated at φ_o = 0) is turned about z by φ_o.
//  2-D table: bilinear over the parabolic map (ω.x, ω.y)/(1+ω.z) on the grid −1 + 2i/(S−1).
#include <algorithm>
#include <cmath>

#include "sh/reference.h"
#include "sh/reference_checks.h"
#include "sh/sh_basis.h"

namespace rc::ref {
namespace {

void validate(const char* fn, const BrdfDotBatch& b) {
  detail::checkOrder(fn, b.order);
  detail::checkCount(fn, "points", b.points);
  detail::checkSize(fn, "lambda", b.lambda.size(), 3LL * b.order * b.order * b.points);
  detail::checkSize(fn, "wo", b.wo.size(), 3LL * b.points);
  detail::checkSize(fn, "material", b.material.size(), b.points);
  for (size_t t = 0; t < b.tables.size(); ++t) {
    const RcBrdfTable& tb = b.tables[t];
    const std::string name = std::string("ref::") + fn + ": table " + std::to_string(t) + ": ";
    if (tb.kind != RC_TABLE_ISOTROPIC_1D && tb.kind != RC_TABLE_ANISOTROPIC_2D)
      throw Error(name + "unknown kind " + std::to_string(tb.kind));
    if (tb.order < 1 || tb.order > kMaxReferenceOrder) throw Error(name + "order " + std::to_string(tb.order) + " outside 1..20");
    const int minRes = tb.kind == RC_TABLE_ISOTROPIC_1D ? 1 : 2;
    if (tb.res < minRes) throw Error(name + "resolution " + std::to_string(tb.res) + " below " + std::to_string(minRes));
    const long long entries = tb.kind == RC_TABLE_ISOTROPIC_1D ? tb.res : 1LL * tb.res * tb.res;
    const long long need = entries * 3 * tb.order * tb.order;
    if (tb.offset < 0 || tb.offset + need > static_cast<long long>(b.tableData.size()))
      throw Error(name + "[" + std::to_string(tb.offset) + ", " + std::to_string(tb.offset + need) +
                  ") exceeds tableData of " + std::to_string(b.tableData.size()) + " floats");
  }
}

// Linear interpolation coordinate on a grid of `res` nodes: node i0 and fraction f in [0, 1].
void gridCoord(double u, int res, int& i0, double& f) {
  if (res < 2) {
    i0 = 0;
    f = 0;
    return;
  }
  i0 = std::clamp(static_cast<int>(std::floor(u)), 0, res - 2);
  f = std::clamp(u - i0, 0.0, 1.0);
}

}  // namespace

void brdfDotRange(const BrdfDotBatch& batch, std::vector<float>& out, int begin, int end) {
  const char* fn = "brdfDotRange";
  validate(fn, batch);
  detail::checkSize(fn, "out", out.size(), 3LL * batch.points);
  detail::checkRange(fn, begin, end, batch.points);
  const int n2 = batch.order * batch.order;
  std::vector<double> F, Fr;
  for (int p = begin; p < end; ++p) {
    const int mat = batch.material[p];
    if (mat < 0 || mat >= static_cast<int>(batch.tables.size()))
      throw Error(std::string("ref::") + fn + ": point " + std::to_string(p) + " has material " + std::to_string(mat) +
                  " of " + std::to_string(batch.tables.size()) + " tables");
    const RcBrdfTable& tb = batch.tables[mat];
    const double wx = batch.wo[3 * p], wy = batch.wo[3 * p + 1], wz = batch.wo[3 * p + 2];
    float* dst = out.data() + 3LL * p;
    if (!(wz > 0)) {  // below (or on) the horizon, or NaN
      dst[0] = dst[1] = dst[2] = 0.0f;
      continue;
    }
    const int tn2 = tb.order * tb.order, stride = 3 * tn2;
    const float* data = batch.tableData.data() + tb.offset;
    F.assign(stride, 0.0);
    if (tb.kind == RC_TABLE_ISOTROPIC_1D) {
      const double x = std::sqrt(wx * wx + wy * wy) / (1.0 + wz);
      int i0;
      double f;
      gridCoord(x * (tb.res - 1), tb.res, i0, f);
      const float* a = data + 1LL * stride * i0;
      const float* b = tb.res > 1 ? a + stride : a;
      for (int i = 0; i < stride; ++i) F[i] = (1 - f) * a[i] + f * b[i];
      const double phi = std::atan2(wy, wx);
      Fr.resize(stride);
      for (int c = 0; c < 3; ++c) sh::rotateZ(tb.order, phi, F.data() + c * tn2, Fr.data() + c * tn2);
      F.swap(Fr);
    } else {
      const double px = wx / (1.0 + wz), py = wy / (1.0 + wz);
      int ix, iy;
      double fx, fy;
      gridCoord((px + 1.0) * 0.5 * (tb.res - 1), tb.res, ix, fx);
      gridCoord((py + 1.0) * 0.5 * (tb.res - 1), tb.res, iy, fy);
      const float* n00 = data + 1LL * stride * (iy * tb.res + ix);
      const float* n01 = n00 + stride;                      // ix + 1
      const float* n10 = n00 + 1LL * stride * tb.res;       // iy + 1
      const float* n11 = n10 + stride;
      for (int i = 0; i < stride; ++i)
        F[i] = (1 - fy) * ((1 - fx) * n00[i] + fx * n01[i]) + fy * ((1 - fx) * n10[i] + fx * n11[i]);
    }
    // Missing coefficients on either side are zero: sum over the common bands.
    const int common = std::min(batch.order, tb.order), cn2 = common * common;
    const float* lam = batch.lambda.data() + 3LL * n2 * p;
    for (int c = 0; c < 3; ++c) {
      double s = 0;
      for (int i = 0; i < cn2; ++i) s += double(lam[c * n2 + i]) * F[c * tn2 + i];
      dst[c] = static_cast<float>(s);
    }
  }
}

void brdfDot(const BrdfDotBatch& batch, std::vector<float>& out) {
  validate("brdfDot", batch);
  out.assign(3ULL * batch.points, 0.0f);
  brdfDotRange(batch, out, 0, batch.points);
}

}  // namespace rc::ref
