#pragma once
// Adaptive sampling, shared by both integrators (--adaptive T, --max-spp N). A pixel's error is
// estimated from its own samples: after n samples, |mean of all n − mean of the first n/2| is an
// estimate of the error of the mean of all n (for independent halves its variance is exactly
// σ²/n). In the relMSE form of the image metrics (core/image_metrics.h)
//   e² = mean over RGB of (m_n − m_{n/2})² / (m_n² + 0.01),
// and a pixel goes on when the largest e² in its (2·kAdaptiveWindow+1)² neighbourhood exceeds T²:
// it takes as many samples again (its sample indices n … 2n−1, so a low-discrepancy pixel keeps a
// (0,m,2)-net at every power of two), until the neighbourhood is below T or it reaches max_spp.
// The neighbourhood is what finds rare features: a pixel 1 % covered by a bright emitter whose
// first 64 samples all missed it has e = 0 on its own, but its neighbours along the edge caught it.
//
// Where it pays: a radiance-cached image's remaining noise sits in few pixels (the edges of a
// visible emitter: 67 % of relMSE in 1 % of the pixels of the 512² Cornell box at 64 spp), which
// then get their samples alone. It is consistent, not unbiased: whether a pixel goes on depends
// on its samples (as in every production renderer's adaptive sampling); as T → 0 the image
// converges to the non-adaptive one at max_spp.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/math.h"

namespace rc {

struct AdaptiveSettings {
  float threshold = 0.0f;  // relative RMS error per pixel; 0 = off
  int maxSpp = 0;          // 0 = kDefaultMaxSppFactor × spp
  bool enabled() const { return threshold > 0.0f; }
};
// Default cap: edge pixels converge like a 16× larger sample count without the cost elsewhere.
constexpr int kDefaultMaxSppFactor = 16;
// Neighbourhood radius of the error estimate (pixels).
constexpr int kAdaptiveWindow = 2;
int effectiveMaxSpp(const AdaptiveSettings& s, int spp);

// The samples [first, end) a pixel takes in a round.
struct SampleRange {
  int first = 0, end = 0;
  int count() const { return end - first; }
};

// The adaptive state of a width × height image, pixels indexed y·width + x. Pixels are written
// by one thread each at a time (tiles, bands), so add() needs no lock.
class AdaptivePixels {
 public:
  // firstSample: the sample indices of round 0 are [firstSample, firstSample + spp) (a later pass
  // of a progressive render, render/progressive.h); > 0 only without adaptive sampling.
  AdaptivePixels(int width, int height, int spp, const AdaptiveSettings& settings, int firstSample = 0);
  // The samples each pixel takes in the current round (round 0: [firstSample, firstSample + spp)).
  const std::vector<SampleRange>& ranges() const { return ranges_; }
  // Forget pixels [begin, end): they are about to take their spp first samples again.
  void restart(size_t begin, size_t end);
  // Sample `sampleIndex` of pixel `p` (its radiance, finite) from the current round.
  void add(size_t p, int sampleIndex, const Color& L);
  // Ends the round: sets ranges() to the next round's samples (count 0 for pixels that are done).
  // Returns false when no pixel takes more (always false when adaptive sampling is off).
  bool nextRound();
  int samplesOf(size_t p) const { return px_[p].n; }
  // Squared relative error estimate of pixel p alone (infinite with fewer than two samples).
  float errorSquared(size_t p) const;
  // Samples taken in all, pixels that took more than spp, the most any pixel took.
  uint64_t totalSamples() const;
  uint64_t pixelsAboveSpp() const;
  int maxSamples() const;

 private:
  struct Pixel {
    double all[3] = {0, 0, 0};   // Σ L over samples [0, n)
    double half[3] = {0, 0, 0};  // Σ L over samples [0, halfN)
    int n = 0, halfN = 0;
  };
  AdaptiveSettings settings_;
  int width_, height_, spp_, maxSpp_, first_;
  std::vector<Pixel> px_;
  std::vector<SampleRange> ranges_;
  std::vector<float> error_;   // errorSquared per pixel, as of the last round
  std::vector<float> rowMax_;  // max of error_ over each pixel's row neighbourhood (±kAdaptiveWindow)
  std::vector<char> dirty_;    // samples added since error_ was computed (one writer per pixel)
  std::vector<char> rowHasRange_;  // rows holding a pixel whose current range is not empty
};

struct RenderStats;  // render/integrator.h
// The render statistics of adaptive sampling (both integrators): threshold, cap, mean samples per
// pixel, the fraction of pixels that took more than spp, the most any pixel took.
void reportAdaptiveSampling(RenderStats& stats, const AdaptiveSettings& settings, int spp, uint64_t samples,
                            uint64_t pixelsAboveSpp, int maxSamples, double pixels);

}  // namespace rc
