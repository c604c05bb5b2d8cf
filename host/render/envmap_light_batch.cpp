// EnvmapLight's passes over a wave: lookupAdd (the envmap along many directions) and sampleWave
// (many light samples), each a few loops over arrays, one lane per direction or sample.
//
// The loop bodies are the scalar calls' own (render/envmap_texels.h, Distribution1D's steps); the
// texel and table lookups become gathers. Baseline x86-64 has no gather, so each pass is also
// compiled for AVX2 and AVX-512 and picked at run time (core/simd_level.h, runSimd). Each lane
// must compute what the scalar call computes, bit for bit (tests/render/envmap_light_batch_test.cpp
// checks every version the CPU runs): no version may contract a·b + c into an FMA (one rounding
// instead of two) — the targets do not include FMA, and CMakeLists.txt builds this file with
// -ffp-contract=off as well. Its other two flags change no value: -fno-math-errno lets sqrt be the
// instruction alone (no branch to set errno), and -fno-trapping-math lets a select evaluate both of
// its sides (a division, a float → int conversion), which is what makes the loop bodies free of
// branches and so vectorisable.
#include <algorithm>
#include <cstring>

#include "render/envmap_light.h"

namespace rc {

#define RC_LANES_PASS [&]() __attribute__((always_inline))

void EnvmapLight::lookupAdd(const float* x, const float* y, const float* z, size_t n, float selectProb, float* r,
                            float* g, float* b, float* pdf, SimdLevel level) const {
  const EnvmapTexels t = tables();
  float* __restrict R = r;
  float* __restrict G = g;
  float* __restrict B = b;
  float* __restrict P = pdf;
  runSimd(level, RC_LANES_PASS {
    if (P) {
#pragma GCC ivdep
      for (size_t k = 0; k < n; ++k) {
        const Vec3 d = t.local(Vec3(x[k], y[k], z[k]));
        const Vec2 uv = envUv(d);
        const Color c = t.bilinear(uv);
        R[k] += c.r;
        G[k] += c.g;
        B[k] += c.b;
        P[k] += selectProb * t.pdf(d, uv);
      }
    } else {
#pragma GCC ivdep
      for (size_t k = 0; k < n; ++k) {
        const Color c = t.bilinear(envUv(t.local(Vec3(x[k], y[k], z[k]))));
        R[k] += c.r;
        G[k] += c.g;
        B[k] += c.b;
      }
    }
  });
}

namespace {

// Distribution1D::sampleTable for n lanes: lane k's u[k] in the table of `bins` bins that starts
// at cdf + table(k). Its bin is the last cdf entry ≤ u (then clamped, empty bins skipped, as there);
// sampleTable narrows the search through the guide table, here every lane runs a binary search
// over the whole table — the same entry, in the same steps for every lane, so that each step is one
// loop over the lanes (a gather and a select). *remapped gets u rescaled within the bin.
template <class TableStart>
void searchLanes(SimdLevel level, const double* cdf, size_t bins, const TableStart& table, const float* u, size_t n,
                 int32_t* __restrict bin, float* __restrict remapped) {
  runSimd(level, RC_LANES_PASS {
    for (size_t k = 0; k < n; ++k) bin[k] = 0;
    for (size_t len = bins + 1; len > 1;) {
      const int32_t half = static_cast<int32_t>(len / 2);
#pragma GCC ivdep
      for (size_t k = 0; k < n; ++k) {
        const int32_t b = bin[k];
        bin[k] = cdf[table(k) + b + half] <= static_cast<double>(u[k]) ? b + half : b;
      }
      len -= half;
    }
  });
  for (size_t k = 0; k < n; ++k)  // rarely more than a compare: a bin found this way is seldom empty
    bin[k] = static_cast<int32_t>(Distribution1D::skipEmptyBins(
        cdf + table(k), bins, std::min(static_cast<size_t>(bin[k]), bins - 1)));
  runSimd(level, RC_LANES_PASS {
#pragma GCC ivdep
    for (size_t k = 0; k < n; ++k) remapped[k] = Distribution1D::remapInBin(cdf + table(k), bin[k], u[k]);
  });
}

// x where mask is all ones, +0 where it is 0.
inline float masked(float x, uint32_t mask) {
  uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits &= mask;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

}  // namespace

void EnvmapLight::SampleWave::fit(size_t n) {
  for (std::vector<float>* a : {&ux, &uy, &dx, &dy, &dz, &r, &g, &b, &pdf, &u, &v, &sinTheta})
    if (a->size() < n) a->resize(n);
  for (std::vector<int32_t>* a : {&row, &column})
    if (a->size() < n) a->resize(n);
}

void EnvmapLight::sampleWave(SampleWave& w, size_t n, SimdLevel level) const {
  const EnvmapTexels t = tables();
  // The cell (sample()'s cells_.sample): the row from the marginal, the column from that row's
  // conditional; w.u and w.v hold the remapped numbers, then the sampled (u, v).
  const size_t columns = cells_.cols();
  searchLanes(level, cells_.rowCdf(), cells_.rows(), [](size_t) { return size_t{0}; }, w.uy.data(), n, w.row.data(),
              w.v.data());
  const int32_t* row = w.row.data();
  searchLanes(level, cells_.columnCdfs(), columns, [&](size_t k) { return static_cast<size_t>(row[k]) * (columns + 1); },
              w.ux.data(), n, w.column.data(), w.u.data());
  float* __restrict u = w.u.data();
  float* __restrict v = w.v.data();
  const int32_t* __restrict column = w.column.data();
  runSimd(level, RC_LANES_PASS {
#pragma GCC ivdep
    for (size_t k = 0; k < n; ++k) {
      const Vec2 uv = t.cellUv(column[k], row[k], u[k], v[k]);
      u[k] = uv.x;
      v[k] = uv.y;
    }
  });
  // The local direction: libm's sin and cos, one lane at a time (a vector polynomial would round
  // differently from sample()'s).
  for (size_t k = 0; k < n; ++k) {
    const Vec3 d = envDirection(u[k], v[k], &w.sinTheta[k]);
    w.dx[k] = d.x, w.dy[k] = d.y, w.dz[k] = d.z;
  }
  float* __restrict dx = w.dx.data();
  float* __restrict dy = w.dy.data();
  float* __restrict dz = w.dz.data();
  float* __restrict r = w.r.data();
  float* __restrict g = w.g.data();
  float* __restrict b = w.b.data();
  float* __restrict pdf = w.pdf.data();
  const float* __restrict sinTheta = w.sinTheta.data();
  const int width = width_;
  runSimd(level, RC_LANES_PASS {
#pragma GCC ivdep
    for (size_t k = 0; k < n; ++k) {
      const Vec3 d = t.world(Vec3(dx[k], dy[k], dz[k]));
      dx[k] = d.x, dy[k] = d.y, dz[k] = d.z;
      // Nothing at the poles (no solid angle): sample()'s early return, as a mask on values computed
      // for every lane (a select would let the compiler move the lookups under it, as masked
      // gathers that AVX2 lacks).
      const uint32_t keep = sinTheta[k] > 0.0f ? ~0u : 0u;
      const Color c = t.bilinear(Vec2(u[k], v[k]));
      const float p = t.cellPdf(static_cast<size_t>(row[k]) * width + column[k], sinTheta[k]);
      r[k] = masked(c.r, keep);
      g[k] = masked(c.g, keep);
      b[k] = masked(c.b, keep);
      pdf[k] = masked(p, keep);
    }
  });
}

#undef RC_LANES_PASS

}  // namespace rc
