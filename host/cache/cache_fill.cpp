#include "cache/cache_fill.h"

#include <algorithm>

#include "cache/rng_salts.h"
#include "core/json_writer.h"
#include "core/parallel.h"
#include "core/rng.h"
#include "core/timing.h"
#include "render/direct_light.h"
#include "render/surface_edges.h"

namespace rc {

namespace {

constexpr int kFillStrides[] = {16, 8, 4, 2, 1};
// Points per engine call: bounds memory (≈ 0.3 KB a point) and gives progress/cancel points. Each
// call ends in rounds that place a few records at the last uncovered points, at a fixed cost per
// round (two dozen parallel loops and a handful of kernel calls) that a round of one record cannot
// spread over the threads: fewer, bigger calls have fewer such rounds.
constexpr size_t kPointsPerCall = 32768;

// The film positions one pass looks up, with their pixels and shade-point seeds.
struct PassPoints {
  std::vector<Vec2> pos;
  std::vector<int> pixel;
  std::vector<uint64_t> seed;
};

// The last pass (stride 1) looks up the centres of the four quadrants of pixels at surface edges:
// the final pass's jittered samples then find records on every surface a pixel shows, also faces
// that only a sub-pixel sliver of it sees, instead of creating them during shading (which means
// shading earlier bands again). Inside a surface the pixel's centre is enough: a jittered sample
// lies within 0.71 px of it and the final pass's relaxed lookup reaches twice a record's radius
// (r_min ≥ 1.5 px). Quadrants in every pixel would cost 4 lookups per pixel; at edges only, the
// shipped scenes shade no band again (bands_reshaded = 0, tested).
PassPoints passPoints(const RcacheRun& run, int stride, const std::vector<uint8_t>& edges,
                      std::vector<char>& visited) {
  const int W = run.width, H = run.height;
  PassPoints pts;
  for (int y = 0; y < H; y += stride)
    for (int x = 0; x < W; x += stride) {
      const size_t id = static_cast<size_t>(y) * W + x;
      if (stride == 1 && edges[id]) {
        for (int q = 0; q < 4; ++q) {
          pts.pos.emplace_back(x + 0.25f + 0.5f * (q & 1), y + 0.25f + 0.5f * (q >> 1));
          pts.pixel.push_back(static_cast<int>(id));
          pts.seed.push_back(hashMix(run.seed, id, kSaltFillQuadrant + q));
        }
        continue;
      }
      if (visited[id]) continue;
      visited[id] = 1;
      pts.pos.emplace_back(x + 0.5f, y + 0.5f);
      pts.pixel.push_back(static_cast<int>(id));
      pts.seed.push_back(hashMix(run.seed, id, kSaltFillCentre));
    }
  return pts;
}

// Makes the caches cover the points [begin, end) of a pass.
void fillPoints(const RcacheRun& run, const PassPoints& pass, size_t begin, size_t end) {
  std::vector<Primary> prim;
  run.primaries.trace({pass.pos.begin() + begin, pass.pos.begin() + end},
                      {pass.pixel.begin() + begin, pass.pixel.begin() + end},
                      {pass.seed.begin() + begin, pass.seed.begin() + end}, prim);
  std::vector<ShadePoint> pts(prim.size());
  for (size_t i = 0; i < prim.size(); ++i) pts[i] = prim[i].sp;
  // Weber thresholds are relative to what the viewer sees: direct light + emission.
  std::vector<float> base(pts.size(), 0.0f);
  if (run.params.adaptive) {
    parallelFor(pts.size(), 64, [&](size_t b, size_t e) {
      for (size_t i = b; i < e; ++i) {
        if (!isCached(run.engine.technique(pts[i]))) continue;
        Rng rng(pts[i].seed, kStreamFillDirectLight);
        BsdfPtr pointBsdf;  // a spatially varying BSDF at this point (Bsdf::at)
        const Bsdf& bsdf = bsdfAt(*run.ctx.scene.bsdfs[pts[i].hit.bsdf], pts[i], pointBsdf);
        const Color d = directLight(run.ctx, pts[i].hit, pts[i].frame, pts[i].wo, bsdf, rng);
        base[i] = luminance(d + prim[i].Le);
      }
    });
  }
  run.engine.fill(pts, base, true);
}

}  // namespace

FillReport fillCache(const RcacheRun& run) {
  const auto start = SteadyClock::now();
  const PhaseCpuMeter cpu;
  FillReport report;
  JsonWriter passes;
  passes.beginArray();
  std::vector<char> visited(static_cast<size_t>(run.width) * run.height, 0);
  for (int stride : kFillStrides) {
    if (report.interrupted) break;
    const auto passStart = SteadyClock::now();
    const size_t recordsBefore = run.totalRecords();
    std::vector<uint8_t> edges;
    if (stride == 1) {
      edges = surfaceEdgePixels(run.ctx.accel, run.camera, run.width, run.height);
      report.edgePixels = static_cast<size_t>(std::count(edges.begin(), edges.end(), uint8_t(1)));
    }
    const PassPoints pass = passPoints(run, stride, edges, visited);
    for (size_t begin = 0; begin < pass.pos.size(); begin += kPointsPerCall) {
      if (run.cancelled()) {
        report.interrupted = true;
        break;
      }
      const size_t end = std::min(pass.pos.size(), begin + kPointsPerCall);
      fillPoints(run, pass, begin, end);
      if (run.ctx.progress)
        run.ctx.progress("cache fill (stride " + std::to_string(stride) + ")", double(end), double(pass.pos.size()));
    }
    passes.beginObject()
        .field("stride", stride)
        .field("points", pass.pos.size())
        .field("records", run.totalRecords() - recordsBefore)
        .field("time_s", secondsSince(passStart))
        .endObject();
  }
  passes.endArray();
  report.passesJson = passes.str();
  report.seconds = secondsSince(start);
  report.cpu = cpu.elapsed();
  return report;
}

}  // namespace rc
