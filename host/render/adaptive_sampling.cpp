#include "render/adaptive_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "render/integrator.h"

namespace rc {

int effectiveMaxSpp(const AdaptiveSettings& s, int spp) {
  if (!s.enabled()) return spp;
  const long long cap = s.maxSpp > 0 ? s.maxSpp : static_cast<long long>(kDefaultMaxSppFactor) * spp;
  return static_cast<int>(std::clamp<long long>(cap, spp, 1 << 20));
}

AdaptivePixels::AdaptivePixels(int width, int height, int spp, const AdaptiveSettings& settings, int firstSample)
    : settings_(settings), width_(width), height_(height), spp_(spp), maxSpp_(effectiveMaxSpp(settings, spp)),
      first_(firstSample),
      px_(static_cast<size_t>(width) * height), ranges_(px_.size()), error_(px_.size(), 0.0f),
      rowMax_(px_.size(), 0.0f), dirty_(px_.size(), 1), rowHasRange_(static_cast<size_t>(height), 0) {
  // A pixel's error estimate compares its first samples with all of them, from index 0.
  if (settings.enabled() && firstSample != 0) throw Error("adaptive sampling: not in a later progressive pass");
  restart(0, px_.size());
}

void AdaptivePixels::restart(size_t begin, size_t end) {
  for (size_t p = begin; p < end; ++p) {
    px_[p] = Pixel{};
    px_[p].n = spp_;
    px_[p].halfN = spp_ / 2;
    ranges_[p] = SampleRange{first_, first_ + spp_};
    dirty_[p] = 1;
    rowHasRange_[p / static_cast<size_t>(width_)] = 1;
  }
}

void AdaptivePixels::add(size_t p, int sampleIndex, const Color& L) {
  if (!settings_.enabled()) return;  // only the sample counts matter then
  Pixel& px = px_[p];
  dirty_[p] = 1;
  for (int c = 0; c < 3; ++c) {
    px.all[c] += L[c];
    if (sampleIndex < px.halfN) px.half[c] += L[c];
  }
}

float AdaptivePixels::errorSquared(size_t p) const {
  const Pixel& px = px_[p];
  if (px.halfN <= 0 || px.n <= px.halfN) return std::numeric_limits<float>::infinity();
  double e = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double mAll = px.all[c] / px.n, mHalf = px.half[c] / px.halfN;
    e += (mAll - mHalf) * (mAll - mHalf) / (mAll * mAll + 0.01);
  }
  return static_cast<float>(e / 3.0);
}

bool AdaptivePixels::nextRound() {
  const size_t W = static_cast<size_t>(width_), H = static_cast<size_t>(height_);
  // Last round's ranges end.
  for (size_t y = 0; y < H; ++y) {
    if (!rowHasRange_[y]) continue;
    rowHasRange_[y] = 0;
    for (size_t p = y * W; p < (y + 1) * W; ++p) ranges_[p] = SampleRange{px_[p].n, px_[p].n};
  }
  if (!settings_.enabled()) return false;
  // Error estimates, and the row maxima of the separable max filter, change only in rows that
  // took samples since the last round; a pixel decides differently from last round only if its
  // neighbourhood holds such a row (it was then refined and took samples itself, or it was
  // below the threshold or at the cap and still is). So each round touches the rows around the
  // pixels still being refined, not the whole image: late rounds refine a few hundred pixels.
  std::vector<char> rowDirty(H, 0);
  bool anyDirty = false;
  for (size_t y = 0; y < H; ++y)
    for (size_t p = y * W; p < (y + 1) * W; ++p) {
      if (!dirty_[p]) continue;
      error_[p] = errorSquared(p);
      dirty_[p] = 0;
      rowDirty[y] = 1;
      anyDirty = true;
    }
  if (!anyDirty) return false;
  const size_t R = static_cast<size_t>(kAdaptiveWindow);
  for (size_t y = 0; y < H; ++y) {
    if (!rowDirty[y]) continue;
    for (size_t x = 0; x < W; ++x) {
      float m = 0.0f;
      for (size_t u = x > R ? x - R : 0; u <= std::min(W - 1, x + R); ++u) m = std::max(m, error_[y * W + u]);
      rowMax_[y * W + x] = m;
    }
  }
  const float t2 = settings_.threshold * settings_.threshold;
  bool any = false;
  for (size_t y = 0; y < H; ++y) {
    const size_t v0 = y > R ? y - R : 0, v1 = std::min(H - 1, y + R);
    bool near = false;
    for (size_t v = v0; v <= v1 && !near; ++v) near = rowDirty[v] != 0;
    if (!near) continue;
    for (size_t x = 0; x < W; ++x) {
      float m = 0.0f;
      for (size_t v = v0; v <= v1; ++v) m = std::max(m, rowMax_[v * W + x]);
      Pixel& px = px_[y * W + x];
      if (px.n >= maxSpp_ || !(m > t2)) continue;
      // The samples so far become the "first half" of the doubled set.
      std::copy(px.all, px.all + 3, px.half);
      px.halfN = px.n;
      px.n = std::min(maxSpp_, 2 * px.n);
      ranges_[y * W + x] = SampleRange{px.halfN, px.n};
      rowHasRange_[y] = 1;
      any = true;
    }
  }
  return any;
}

uint64_t AdaptivePixels::totalSamples() const {
  uint64_t s = 0;
  for (const Pixel& p : px_) s += static_cast<uint64_t>(p.n);
  return s;
}

uint64_t AdaptivePixels::pixelsAboveSpp() const {
  uint64_t k = 0;
  for (const Pixel& p : px_) k += p.n > spp_ ? 1 : 0;
  return k;
}

int AdaptivePixels::maxSamples() const {
  int m = 0;
  for (const Pixel& p : px_) m = std::max(m, p.n);
  return m;
}

void reportAdaptiveSampling(RenderStats& stats, const AdaptiveSettings& settings, int spp, uint64_t samples,
                            uint64_t pixelsAboveSpp, int maxSamples, double pixels) {
  if (!settings.enabled()) {
    stats.setText("adaptive_sampling", "off");
    return;
  }
  stats.setText("adaptive_sampling", "on");
  stats.set("adaptive_threshold", settings.threshold);
  stats.set("adaptive_max_spp", effectiveMaxSpp(settings, spp));
  stats.set("samples_per_pixel_mean", pixels > 0 ? double(samples) / pixels : 0.0);
  stats.set("adaptive_pixels_fraction", pixels > 0 ? double(pixelsAboveSpp) / pixels : 0.0);
  stats.set("samples_per_pixel_max", maxSamples);
}

}  // namespace rc
