#pragma once
// Where the cost pilot (cache/cost_pilot.h) cannot afford to try any cache candidate within its
// budget, whether the fill can pay at all, predicted from the share pilot's figures and a few path
// samples at pilot points, not guessed: before, the share pilot's verdict stood there, and on
// geometry whose records serve only a few pixels (the lego scene at 256²–512², bench/RESULTS.md)
// the fill then cost a hundred times the path tracer's whole render.
//
// Cost and error per pixel of the image, in rays, for a render of N samples per pixel (under an
// independent sampler: errors that fall as 1/N; under a low-discrepancy one the direct light's
// falls faster, the shares below do not hold, and nothing is predicted — on aniso_sphere at 96²,
// 32 spp the prediction said 1.5× against the cache where it was 10× cheaper in rays):
// - the path tracer: N·L rays (L: its rays per pixel sample, counted at the pilot's points) for
//   a relMSE of V/N, V = V_d + V_i its one-sample variance, direct (emission and the first
//   vertex's light) and indirect (the rest);
// - rcache: the fill, h·c/m records per pixel (h: share of pixels with a surface hit, c: share of
//   hits whose own material makes records, m: pixels a level-0 record serves, from the coherence
//   test's q as record_coherence.h relates them: m = πρ², ρ = 2δ/(π(1 − q)), at most π·r_max²)
//   at 2S rays each (S record rays and about as many shading their hits; lego17 counted 1050 rays
//   per record at S = 512), plus the final pass's (1 + o)·N·L (o = 0.3, path_fallback.h). Its
//   error: the direct part as the path tracer's, V_d/N; the indirect part of the served share s
//   at best as one record's, V_i/S; the rest V_i/N. So with f = V_i/V the path tracer reaches
//   rcache's error at n = N / (1 − f·s + f·s·N/S) samples per pixel. f is measured as what the
//   final pass would leave: 1 − V_kept/V, V_kept the variance of the emission seen plus the
//   light-sampling half of the direct light from the lights records do not carry (the light
//   split's residual) at points whose own material is cached, and of the whole path elsewhere —
//   so the unserved points are in it, and s = 1.
// The fill pays where rcache's rays are at most the path tracer's at that error:
//   h·c·2S/m + (1 + o)·N·L ≤ n·L.
// Approximated, in the cache's favour where not said: only level-0 records are counted (level-1 records and
// the paths continued below them are left out; on lego they were 4 per level-0 record), a
// record's error is its own noise only (no interpolation error; blending several records would
// lower it, but by less than the interpolation adds at the floor radius), rays of every kind cost
// alike, points served only through their continuation count as unserved (against the cache),
// and V and V_kept come from two samples each at 64–1024 points (at most 1/64 of the render's
// samples), each weighted as relMSE weights its pixel (the covariance of the parts counted as
// removable); f is the median of 8 interleaved groups of points (a pooled one is noisy).
#include <cstddef>
#include <string>

#include "cache/path_fallback.h"
#include "cache/rcache_run.h"

namespace rc {

// The figures of the prediction above, per pixel of the image.
struct FillPayoffFigures {
  int spp = 1;                  // N
  double hitShare = 1.0;        // h
  double recordShare = 1.0;     // c
  double servedShare = 1.0;     // s
  double pixelsPerRecord = 1.0; // m
  double recordRays = 512.0;    // S
  double raysPerSample = 1.0;   // L
  double indirectShare = 1.0;   // f
  double overhead = 0.3;        // o
};

// m from the coherence test's q at offset δ pixels: πρ² with ρ = 2δ/(π(1 − q)), at most π·rMaxPx².
double pixelsPerRecord(double q, double offsetPx, double rMaxPx);

struct FillPayoff {
  bool measured = false;   // the prediction ran (reason says why not where it did not)
  bool pays = true;
  FillPayoffFigures figures;
  double fillRays = 0.0;      // h·c·2S/m, per pixel
  double cacheRays = 0.0;     // fill + (1 + o)·N·L
  double pathEqualSpp = 0.0;  // n
  double pathRays = 0.0;      // n·L
  std::string reason;
};

// The prediction on given figures (pure; the tests feed it synthetic ones).
FillPayoff predictFillPayoff(const FillPayoffFigures& figures);

// Measures L and f at pilot points and predicts with the share pilot's figures `share` (which must
// have run its coherence test).
FillPayoff measureFillPayoff(const RcacheRun& run, const IntegratorSettings& settings, const FallbackDecision& share);

// Statistics: fill_payoff (the decision and its figures), fill_payoff_rays_per_pixel (rcache's
// predicted), fill_payoff_path_rays_per_pixel (the path tracer's at rcache's error),
// fill_payoff_indirect_share (f), fill_payoff_rays_per_sample (L).
void reportFillPayoff(const FillPayoff& p, RenderStats& stats);

}  // namespace rc
