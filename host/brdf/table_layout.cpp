#include "brdf/table_layout.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace rc {

namespace {

Vec3 nudgeAboveHorizon(double x, double y, double z) {
  // Keep the azimuth, raise the elevation to cos θ = kGrazingCos if the point is lower.
  if (z < kGrazingCos) {
    const double rxy = std::sqrt(x * x + y * y);
    z = kGrazingCos;
    const double s = std::sqrt(1.0 - z * z);
    if (rxy > 0) {
      x = x / rxy * s;
      y = y / rxy * s;
    } else {
      x = s;
      y = 0;
    }
  }
  return Vec3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
}

// Inverse parabolic map: (px, py) = ω.xy / (1 + ω.z)  ⇒  ω.z = (1 − r²)/(1 + r²), ω.xy = 2p/(1 + r²).
Vec3 fromParabolic(double px, double py) {
  double r2 = px * px + py * py;
  if (r2 > 1.0) {  // outside the disk: horizon of the same azimuth
    const double r = std::sqrt(r2);
    px /= r;
    py /= r;
    r2 = 1.0;
  }
  const double d = 1.0 + r2;
  return nudgeAboveHorizon(2.0 * px / d, 2.0 * py / d, (1.0 - r2) / d);
}

}  // namespace

Vec3 isotropicNodeDirection(int t, int T) {
  const double x = T > 1 ? static_cast<double>(t) / (T - 1) : 0.0;
  return fromParabolic(x, 0.0);
}

Vec3 anisotropicNodeDirection(int ix, int iy, int S) {
  const double px = S > 1 ? -1.0 + 2.0 * ix / (S - 1) : 0.0;
  const double py = S > 1 ? -1.0 + 2.0 * iy / (S - 1) : 0.0;
  return fromParabolic(px, py);
}

size_t tableFloatCount(int kind, int order, int res) {
  const size_t per = 3u * static_cast<size_t>(order) * order;
  return kind == RC_TABLE_ANISOTROPIC_2D ? per * res * res : per * res;
}

void rotateAboutZ(int order, double alpha, const double* in, double* out) {
  const int n2 = order * order;
  for (int c = 0; c < 3; ++c) {
    const double* a = in + c * n2;
    double* b = out + c * n2;
    for (int l = 0; l < order; ++l) {
      b[l * (l + 1)] = a[l * (l + 1)];
      for (int m = 1; m <= l; ++m) {
        // f(φ − α): cos m(φ−α) = cos mφ cos mα + sin mφ sin mα, sin m(φ−α) = sin mφ cos mα − cos mφ sin mα.
        const double cm = std::cos(m * alpha), sm = std::sin(m * alpha);
        const double p = a[l * (l + 1) + m], q = a[l * (l + 1) - m];
        b[l * (l + 1) + m] = p * cm - q * sm;
        b[l * (l + 1) - m] = q * cm + p * sm;
      }
    }
  }
}

void lookupTable(const RcBrdfTable& table, const float* data, const Vec3& wo, std::vector<double>& out) {
  const int n2 = table.order * table.order;
  const size_t per = 3u * static_cast<size_t>(n2);
  out.assign(per, 0.0);
  if (!(wo.z > 0.0f)) return;
  const double len = std::sqrt(double(wo.x) * wo.x + double(wo.y) * wo.y + double(wo.z) * wo.z);
  const double x = wo.x / len, y = wo.y / len, z = wo.z / len;
  if (table.kind == RC_TABLE_ISOTROPIC_1D) {
    const int T = table.res;
    const double rxy = std::sqrt(x * x + y * y);
    const double px = rxy / (1.0 + z);  // tan(θ/2)
    const double u = std::clamp(px, 0.0, 1.0) * (T - 1);
    const int i0 = std::min(static_cast<int>(u), std::max(T - 2, 0));
    const int i1 = std::min(i0 + 1, T - 1);
    const double f = u - i0;
    std::vector<double> tmp(per);
    for (size_t k = 0; k < per; ++k)
      tmp[k] = (1.0 - f) * data[i0 * per + k] + f * data[i1 * per + k];
    rotateAboutZ(table.order, std::atan2(y, x), tmp.data(), out.data());
  } else if (table.kind == RC_TABLE_ANISOTROPIC_2D) {
    const int S = table.res;
    auto coord = [&](double p, int& i0, double& f) {
      const double u = std::clamp((p + 1.0) * 0.5, 0.0, 1.0) * (S - 1);
      i0 = std::min(static_cast<int>(u), std::max(S - 2, 0));
      f = u - i0;
    };
    int ix, iy;
    double fx, fy;
    coord(x / (1.0 + z), ix, fx);
    coord(y / (1.0 + z), iy, fy);
    const int ix1 = std::min(ix + 1, S - 1), iy1 = std::min(iy + 1, S - 1);
    const float* c00 = data + (static_cast<size_t>(iy) * S + ix) * per;
    const float* c10 = data + (static_cast<size_t>(iy) * S + ix1) * per;
    const float* c01 = data + (static_cast<size_t>(iy1) * S + ix) * per;
    const float* c11 = data + (static_cast<size_t>(iy1) * S + ix1) * per;
    for (size_t k = 0; k < per; ++k)
      out[k] = (1 - fy) * ((1 - fx) * c00[k] + fx * c10[k]) + fy * ((1 - fx) * c01[k] + fx * c11[k]);
  } else {
    throw Error("lookupTable: unknown table kind " + std::to_string(table.kind));
  }
}

}  // namespace rc
