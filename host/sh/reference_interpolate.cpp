// Scalar reference of interpolate (batches.h): gradient adjustment, rotation into the point's
// frame, normalised weighted sum; per-record and world-frame modes. Double accumulation.
#include <cmath>

#include "sh/reference.h"
#include "sh/reference_checks.h"
#include "sh/sh_basis.h"

namespace rc::ref {
namespace {

void validate(const char* fn, const InterpolateBatch& b) {
  detail::checkOrder(fn, b.order);
  detail::checkCount(fn, "records", b.records);
  detail::checkCount(fn, "points", b.points);
  const long long n = 3LL * b.order * b.order * b.records;
  detail::checkSize(fn, "lambda", b.lambda.size(), n);
  if (b.gradients) {
    detail::checkSize(fn, "gradT", b.gradT.size(), n);
    detail::checkSize(fn, "gradB", b.gradB.size(), n);
  }
  if (!b.worldFrame) detail::checkSize(fn, "recordFrames", b.recordFrames.size(), 9LL * b.records);
  detail::checkSize(fn, "pointFrames", b.pointFrames.size(), 9LL * b.points);
  detail::checkSize(fn, "offsets", b.offsets.size(), 1LL + b.points);
  if (b.offsets[0] != 0) throw Error(std::string("ref::") + fn + ": offsets[0] must be 0");
  for (int p = 0; p < b.points; ++p)
    if (b.offsets[p + 1] < b.offsets[p])
      throw Error(std::string("ref::") + fn + ": offsets decrease at point " + std::to_string(p));
  detail::checkSize(fn, "entries", b.entries.size(), b.offsets[b.points]);
}

void checkEntry(const char* fn, const InterpolateBatch& b, const RcContribution& e, int p) {
  if (e.record < 0 || e.record >= b.records)
    throw Error(std::string("ref::") + fn + ": point " + std::to_string(p) + " names record " +
                std::to_string(e.record) + " of " + std::to_string(b.records));
  if (!std::isfinite(e.weight) || e.weight < 0.0f || !std::isfinite(e.dt) || !std::isfinite(e.db))
    throw Error(std::string("ref::") + fn + ": point " + std::to_string(p) + " has a non-finite or negative weight/displacement");
}

}  // namespace

void interpolateRange(const InterpolateBatch& batch, std::vector<float>& out, int begin, int end) {
  const char* fn = "interpolateRange";
  validate(fn, batch);
  const int order = batch.order, n2 = order * order;
  detail::checkSize(fn, "out", out.size(), 3LL * n2 * batch.points);
  detail::checkRange(fn, begin, end, batch.points);
  std::vector<double> v(3 * n2), rv(3 * n2), acc(3 * n2), res(3 * n2);
  for (int p = begin; p < end; ++p) {
    const float* Fp = batch.pointFrames.data() + 9LL * p;
    std::fill(acc.begin(), acc.end(), 0.0);
    double sumW = 0;
    for (int e = batch.offsets[p]; e < batch.offsets[p + 1]; ++e) {
      const RcContribution& c = batch.entries[e];
      checkEntry(fn, batch, c, p);
      const size_t base = 3ULL * n2 * c.record;
      for (int i = 0; i < 3 * n2; ++i) {
        double x = batch.lambda[base + i];
        if (batch.gradients) x += double(c.dt) * batch.gradT[base + i] + double(c.db) * batch.gradB[base + i];
        v[i] = x;
      }
      const double w = c.weight;
      sumW += w;
      if (batch.worldFrame) {
        for (int i = 0; i < 3 * n2; ++i) acc[i] += w * v[i];
      } else {
        const float* Fr = batch.recordFrames.data() + 9LL * c.record;
        double R[9];  // R(a,b) = e_p,a · e_r,b
        for (int a = 0; a < 3; ++a)
          for (int bb = 0; bb < 3; ++bb)
            R[3 * a + bb] = double(Fp[3 * a]) * Fr[3 * bb] + double(Fp[3 * a + 1]) * Fr[3 * bb + 1] +
                            double(Fp[3 * a + 2]) * Fr[3 * bb + 2];
        sh::rotateChannels(order, R, 3, v.data(), rv.data());
        for (int i = 0; i < 3 * n2; ++i) acc[i] += w * rv[i];
      }
    }
    float* dst = out.data() + 3LL * n2 * p;
    if (!(sumW > 0)) {
      std::fill(dst, dst + 3 * n2, 0.0f);
      continue;
    }
    for (int i = 0; i < 3 * n2; ++i) acc[i] /= sumW;
    if (batch.worldFrame) {
      double R[9];  // world → point frame: rows of the point frame
      for (int i = 0; i < 9; ++i) R[i] = Fp[i];
      sh::rotateChannels(order, R, 3, acc.data(), res.data());
    } else {
      res = acc;
    }
    for (int i = 0; i < 3 * n2; ++i) dst[i] = static_cast<float>(res[i]);
  }
}

void interpolate(const InterpolateBatch& batch, std::vector<float>& out) {
  validate("interpolate", batch);
  out.assign(3ULL * batch.order * batch.order * batch.points, 0.0f);
  interpolateRange(batch, out, 0, batch.points);
}

}  // namespace rc::ref
