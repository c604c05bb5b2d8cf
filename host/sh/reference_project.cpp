// Scalar reference of sh_project + grad_accumulate (batches.h; gradient formula in reference.h).
// Double accumulation; the basis is evaluated per sample (no shared matrix), so this stays an
// independent check of the kernels' GEMM formulation.
#include <algorithm>
#include <cmath>

#include "sh/reference.h"
#include "sh/reference_checks.h"
#include "sh/sh_basis.h"

namespace rc::ref {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;

void validate(const char* fn, const ProjectBatch& b) {
  detail::checkOrder(fn, b.order);
  if (b.M < 1 || b.N < 1)
    throw Error(std::string("ref::") + fn + ": cell grid " + std::to_string(b.M) + "x" + std::to_string(b.N) +
                " must be at least 1x1");
  detail::checkCount(fn, "records", b.records);
  if (!(b.minDistance > 0.0f) || !std::isfinite(b.minDistance))
    throw Error(std::string("ref::") + fn + ": minDistance " + std::to_string(b.minDistance) +
                " must be positive and finite");
  const long long mn = static_cast<long long>(b.M) * b.N, B = b.records;
  detail::checkSize(fn, "pattern", b.pattern.size(), 2 * mn);
  detail::checkSize(fn, "phi0", b.phi0.size(), B);
  detail::checkSize(fn, "radiance", b.radiance.size(), 3 * mn * B);
  // Distances are only read for gradients; without gradients an empty array is accepted.
  if (b.gradients || !b.distance.empty()) detail::checkSize(fn, "distance", b.distance.size(), mn * B);
}

void validateOut(const char* fn, const ProjectBatch& b, const ProjectResult& out) {
  const long long n = 3LL * b.order * b.order * b.records;
  detail::checkSize(fn, "out.lambda", out.lambda.size(), n);
  if (b.gradients) {
    detail::checkSize(fn, "out.gradT", out.gradT.size(), n);
    detail::checkSize(fn, "out.gradB", out.gradB.size(), n);
  }
  detail::checkSize(fn, "out.dropped", out.dropped.size(), b.records);
}

// Per-batch constants of the gradient formula (reference.h).
struct GradientGeometry {
  std::vector<double> cj, sj, dTheta;  // boundaries j = 0..M, row heights j = 0..M−1
  double arc = 0;                      // 2 sin(π/N)
  explicit GradientGeometry(int M, int N) : cj(M + 1), sj(M + 1), dTheta(M) {
    for (int j = 0; j <= M; ++j) {
      cj[j] = 1.0 - double(j) / M;
      sj[j] = std::sqrt(std::max(0.0, 1.0 - cj[j] * cj[j]));
    }
    for (int j = 0; j < M; ++j) dTheta[j] = std::acos(cj[j + 1]) - std::acos(cj[j]);
    arc = 2.0 * std::sin(kTwoPi / 2.0 / N);
  }
};

struct Scratch {
  std::vector<double> L, rho, wT, wB, cosMid, sinMid, cosLo, sinLo, y, lam, gT, gB;
};

// Radiance (dropped samples → 0) into sc.L; returns how many samples were dropped.
int gatherRadiance(const ProjectBatch& b, int rec, Scratch& sc) {
  const int MN = b.M * b.N;
  const float* rad = b.radiance.data() + 3LL * MN * rec;
  sc.L.assign(3 * MN, 0.0);
  int dropped = 0;
  for (int s = 0; s < MN; ++s) {
    const float r = rad[3 * s], g = rad[3 * s + 1], bl = rad[3 * s + 2];
    if (!std::isfinite(r) || !std::isfinite(g) || !std::isfinite(bl)) {
      ++dropped;
      continue;
    }
    sc.L[3 * s] = r;
    sc.L[3 * s + 1] = g;
    sc.L[3 * s + 2] = bl;
  }
  return dropped;
}

// Inverse distances (miss → 0, clamp r ≥ minDistance) into sc.rho, and the cell-centre and
// cell-edge azimuth directions into sc.cos/sinMid and sc.cos/sinLo.
void gatherGradientInputs(const ProjectBatch& b, int rec, double phi0, Scratch& sc) {
  const int N = b.N, MN = b.M * N;
  const float* dist = b.distance.data() + 1LL * MN * rec;
  sc.rho.resize(MN);
  for (int s = 0; s < MN; ++s) {
    const float r = dist[s];
    sc.rho[s] = (r > 0.0f && std::isfinite(r)) ? 1.0 / std::max(double(r), double(b.minDistance)) : 0.0;
  }
  sc.cosMid.resize(N);
  sc.sinMid.resize(N);
  sc.cosLo.resize(N);
  sc.sinLo.resize(N);
  for (int k = 0; k < N; ++k) {
    const double mid = kTwoPi * (k + 0.5) / N + phi0, lo = kTwoPi * k / N + phi0;
    sc.cosMid[k] = std::cos(mid);
    sc.sinMid[k] = std::sin(mid);
    sc.cosLo[k] = std::cos(lo);
    sc.sinLo[k] = std::sin(lo);
  }
}

// The per-sample gradient weights sc.wT/sc.wB from the radiance differences across cell edges.
void accumulateEdgeWeights(const ProjectBatch& b, const GradientGeometry& geo, Scratch& sc) {
  const int M = b.M, N = b.N, MN = M * N;
  sc.wT.assign(3 * MN, 0.0);
  sc.wB.assign(3 * MN, 0.0);
  // Elevation edges j = 1..M−1 between (j−1,k) and (j,k), direction û_k; half to each cell.
  for (int j = 1; j < M; ++j) {
    const double f = geo.arc * geo.cj[j] * geo.sj[j];
    for (int k = 0; k < N; ++k) {
      const int s = j * N + k, sUp = s - N;
      const double scale = 0.5 * f * std::max(sc.rho[s], sc.rho[sUp]);
      for (int c = 0; c < 3; ++c) {
        const double e = scale * (sc.L[3 * s + c] - sc.L[3 * sUp + c]);
        sc.wT[3 * s + c] += e * sc.cosMid[k];
        sc.wT[3 * sUp + c] += e * sc.cosMid[k];
        sc.wB[3 * s + c] += e * sc.sinMid[k];
        sc.wB[3 * sUp + c] += e * sc.sinMid[k];
      }
    }
  }
  // Azimuth edges at φ_{k−} between (j,k−1) and (j,k) (k−1 wraps), direction v̂_k.
  for (int j = 0; j < M; ++j) {
    for (int k = 0; k < N; ++k) {
      const int s = j * N + k, sPrev = j * N + (k + N - 1) % N;
      const double scale = 0.5 * geo.dTheta[j] * std::max(sc.rho[s], sc.rho[sPrev]);
      for (int c = 0; c < 3; ++c) {
        const double a = scale * (sc.L[3 * s + c] - sc.L[3 * sPrev + c]);
        sc.wT[3 * s + c] -= a * sc.sinLo[k];
        sc.wT[3 * sPrev + c] -= a * sc.sinLo[k];
        sc.wB[3 * s + c] += a * sc.cosLo[k];
        sc.wB[3 * sPrev + c] += a * sc.cosLo[k];
      }
    }
  }
}

// One pass over the samples: Λ into sc.lam and (if asked) the gradient projections into sc.gT/sc.gB.
void projectSamples(const ProjectBatch& b, double phi0, Scratch& sc) {
  const int M = b.M, N = b.N, order = b.order, n2 = order * order;
  sc.y.resize(n2);
  sc.lam.assign(3 * n2, 0.0);
  if (b.gradients) {
    sc.gT.assign(3 * n2, 0.0);
    sc.gB.assign(3 * n2, 0.0);
  }
  for (int j = 0; j < M; ++j) {
    for (int k = 0; k < N; ++k) {
      const int s = j * N + k;
      const double xi = b.pattern[2 * s], zeta = b.pattern[2 * s + 1];
      const double cosT = 1.0 - (j + xi) / M, sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
      const double phi = kTwoPi * (k + zeta) / N + phi0;
      sh::evalBasis(order, sinT * std::cos(phi), sinT * std::sin(phi), cosT, sc.y.data());
      for (int c = 0; c < 3; ++c) {
        const double Lc = sc.L[3 * s + c];
        double* lam = sc.lam.data() + c * n2;
        if (Lc != 0.0)
          for (int i = 0; i < n2; ++i) lam[i] += Lc * sc.y[i];
        if (b.gradients) {
          const double wt = sc.wT[3 * s + c], wb = sc.wB[3 * s + c];
          double* gt = sc.gT.data() + c * n2;
          double* gb = sc.gB.data() + c * n2;
          for (int i = 0; i < n2; ++i) {
            gt[i] += wt * sc.y[i];
            gb[i] += wb * sc.y[i];
          }
        }
      }
    }
  }
}

void projectOne(const ProjectBatch& b, const GradientGeometry& geo, int rec, ProjectResult& out, Scratch& sc) {
  const int MN = b.M * b.N, n2 = b.order * b.order;
  const double phi0 = b.phi0[rec];
  out.dropped[rec] = gatherRadiance(b, rec, sc);
  if (b.gradients) {
    gatherGradientInputs(b, rec, phi0, sc);
    accumulateEdgeWeights(b, geo, sc);
  }
  projectSamples(b, phi0, sc);
  const double cellArea = kTwoPi / MN;
  const size_t base = 3ULL * n2 * rec;
  for (int i = 0; i < 3 * n2; ++i) {
    out.lambda[base + i] = static_cast<float>(cellArea * sc.lam[i]);
    if (b.gradients) {
      out.gradT[base + i] = static_cast<float>(sc.gT[i]);
      out.gradB[base + i] = static_cast<float>(sc.gB[i]);
    }
  }
}

}  // namespace

void projectRange(const ProjectBatch& batch, ProjectResult& out, int begin, int end) {
  validate("projectRange", batch);
  validateOut("projectRange", batch, out);
  detail::checkRange("projectRange", begin, end, batch.records);
  const GradientGeometry geo(batch.M, batch.N);
  Scratch scratch;
  for (int rec = begin; rec < end; ++rec) projectOne(batch, geo, rec, out, scratch);
}

void project(const ProjectBatch& batch, ProjectResult& out) {
  validate("project", batch);
  const size_t n = 3ULL * batch.order * batch.order * batch.records;
  out.lambda.assign(n, 0.0f);
  out.gradT.assign(batch.gradients ? n : 0, 0.0f);
  out.gradB.assign(batch.gradients ? n : 0, 0.0f);
  out.dropped.assign(batch.records, 0);
  projectRange(batch, out, 0, batch.records);
}

}  // namespace rc::ref
