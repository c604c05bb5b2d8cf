#include "cache/adaptive_rounds.h"

#include <algorithm>
#include <string>
#include <vector>

namespace rc {

namespace {

// Runs of rows are shaded together up to about this many samples (few pixels take more, so one
// engine call spans many rows and its kernel launches stay few); a row alone may exceed it.
constexpr size_t kSamplesPerRun = 65536;
// A gap of this many empty rows ends a run: late rounds refine a few hundred pixels, and a tile
// spanning every row between them (zeroed, then merged) cost more than shading them.
constexpr int kRunGapRows = 8;
// The rounds start over at most once after creating records.
constexpr int kMaxAttempts = 2;

// Per row: the round's samples and the columns [x0, x1) that take them.
struct RowSamples {
  std::vector<size_t> samples;
  std::vector<int> x0, x1;
};

RowSamples rowSamples(const SampleRange* ranges, int W, int H) {
  RowSamples rows{std::vector<size_t>(static_cast<size_t>(H), 0), std::vector<int>(static_cast<size_t>(H), W),
                  std::vector<int>(static_cast<size_t>(H), 0)};
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int c = ranges[static_cast<size_t>(y) * W + x].count();
      if (c <= 0) continue;
      const size_t row = static_cast<size_t>(y);
      rows.samples[row] += static_cast<size_t>(c);
      rows.x0[row] = std::min(rows.x0[row], x);
      rows.x1[row] = std::max(rows.x1[row], x + 1);
    }
  return rows;
}

// One round: shades its runs of rows into `into`.
void shadeRound(const RcacheRun& run, FinalPass& pass, const AdaptivePixels& adaptive, const Film& film,
                Film& into, int round, bool& interrupted) {
  const int W = run.width, H = run.height;
  const SampleRange* ranges = adaptive.ranges().data();
  const RowSamples rows = rowSamples(ranges, W, H);
  for (int y0 = 0; y0 < H && !interrupted;) {
    while (y0 < H && rows.samples[static_cast<size_t>(y0)] == 0) ++y0;
    if (y0 >= H) break;
    size_t samples = 0;
    int y1 = y0, last = y0, x0 = W, x1 = 0;
    while (y1 < H) {
      const size_t row = rows.samples[static_cast<size_t>(y1)];
      if (row == 0) {
        if (y1 - last >= kRunGapRows) break;
        ++y1;
        continue;
      }
      if (samples > 0 && samples + row > kSamplesPerRun) break;
      samples += row;
      x0 = std::min(x0, rows.x0[static_cast<size_t>(y1)]);
      x1 = std::max(x1, rows.x1[static_cast<size_t>(y1)]);
      last = y1++;
    }
    y1 = last + 1;
    if (run.cancelled()) {
      interrupted = true;
      break;
    }
    const size_t begin = static_cast<size_t>(y0) * W, end = static_cast<size_t>(y1) * W;
    auto tile = std::make_unique<TileFilm>(film.makeTile(x0, y0, x1, y1));
    pass.shadeSlices(y0, ranges + begin, end - begin, *tile);
    into.merge(*tile);
    if (run.ctx.progress) run.ctx.progress("render (adaptive " + std::to_string(round) + ")", double(y1), double(H));
    y0 = y1;
  }
}

}  // namespace

std::unique_ptr<Film> runAdaptiveRounds(const RcacheRun& run, FinalPass& pass, AdaptivePixels& adaptive,
                                        const Film& film, bool& interrupted) {
  std::unique_ptr<Film> adaptiveFilm;
  for (int attempt = 0; attempt < kMaxAttempts && !interrupted; ++attempt) {
    const size_t recordsBefore = run.totalRecords();
    adaptiveFilm.reset();
    if (run.ctx.options.adaptive.enabled())
      adaptiveFilm = std::make_unique<Film>(run.ctx.scene.film, run.width, run.height);
    for (int round = 1; !interrupted && adaptive.nextRound(); ++round)
      shadeRound(run, pass, adaptive, film, *adaptiveFilm, round, interrupted);
    if (interrupted || run.totalRecords() == recordsBefore) break;
    for (int band = 0; band < pass.bands(); ++band) pass.shadeBand(band);
    pass.countReshaded(pass.bands());
  }
  return adaptiveFilm;
}

}  // namespace rc
