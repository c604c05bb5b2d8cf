#include "cache/rcache_integrator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "brdf/material_plan.h"
#include "cache/cache_engine.h"
#include "cache/cache_file.h"
#include "cache/cache_params.h"
#include "cl/sh_backend.h"
#include "core/error.h"
#include "core/parallel.h"
#include "render/camera.h"
#include "render/direct_light.h"
#include "render/film.h"
#include "render/light_sampler.h"
#include "render/render_loop.h"
#include "render/surface_edges.h"

namespace rc {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Image passes of the cache fill: pixel grids of these strides, coarse to fine (Křivánek's
// implementation fills in the same spirit; big records land first, later passes fill gaps).
constexpr int kFillStrides[] = {16, 8, 4, 2, 1};
// Points per engine call in the image passes: bounds memory and gives progress/cancel points.
constexpr size_t kPointsPerCall = 8192;
// Final pass: a jittered sample that no record covers (the fill covered pixel centres) first
// tries the records covering it at twice their radius, before a record is made for it (which
// means shading earlier bands again). A sample is at most 0.71 px from its pixel's centre and
// records reach at least r_min = 1.5 px, so on flat surfaces the relaxed lookup nearly always
// succeeds; the interpolation weights are the same formula with a doubled a.
constexpr float kFinalRelaxedScale = 2.0f;

void sceneBounds(const Scene& scene, Vec3& lo, Vec3& hi) {
  lo = Vec3(INFINITY);
  hi = Vec3(-INFINITY);
  for (const Mesh& m : scene.meshes)
    for (const Vec3& p : m.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  for (const Sphere& s : scene.spheres) {
    lo = glm::min(lo, s.center - Vec3(s.radius));
    hi = glm::max(hi, s.center + Vec3(s.radius));
  }
  if (!(lo.x <= hi.x)) {
    lo = Vec3(-1.0f);
    hi = Vec3(1.0f);
  }
}

class RcacheIntegrator : public Integrator {
 public:
  explicit RcacheIntegrator(const IntegratorSettings& s) : settings_(s), params_(parseRcacheParams(s.params)) {}
  std::string name() const override { return "rcache"; }
  Image render(const RenderContext& ctx, RenderStats& stats) override;

 private:
  IntegratorSettings settings_;
  RcacheParams params_;
};

struct Primary {
  ShadePoint sp;
  Vec2 filmPos;
  Color Le{0.0f};
  int px = 0, py = 0;
};

Image RcacheIntegrator::render(const RenderContext& ctxIn, RenderStats& stats) {
  const auto tStart = Clock::now();
  const Scene& scene = ctxIn.scene;
  std::unique_ptr<ShBackend> ownBackend;
  ShBackend* backend = ctxIn.backend;
  if (!backend) {
    ownBackend = makeScalarBackend();
    backend = ownBackend.get();
  }
  RenderContext ctx{ctxIn.scene, ctxIn.accel, ctxIn.lights, ctxIn.options, backend, ctxIn.cancel, ctxIn.progress};
  const int maxDepth = settings_.maxDepth;
  const int spp = ctx.options.spp > 0 ? ctx.options.spp : scene.sampleCount;
  const uint64_t seed = scene.samplerSeed + ctx.options.seed;
  const bool lowDiscrepancy = usesLowDiscrepancy(ctx);
  auto cancelled = [&] { return ctx.cancel && ctx.cancel->load(std::memory_order_relaxed); };

  // Materials: technique, SH order and BRDF×cos tables (nothing is built without cached materials).
  auto t0 = Clock::now();
  BrdfTableSet tables;
  BrdfTableOptions topt;
  topt.orderOverride = params_.order;
  topt.notice = [&](const std::string& msg) { stats.setText("brdf_notice", msg); };
  tables.build(scene.bsdfs, topt);
  const double tablesS = since(t0);

  Film film(scene.film);
  const int W = film.width(), H = film.height();
  CameraModel camera(scene.camera, W, H);
  Vec3 lo, hi;
  sceneBounds(scene, lo, hi);
  CacheEngine engine(ctx, params_, tables, camera, maxDepth, settings_.rrDepth, lo, hi);
  const uint64_t hash = cacheSceneHash(scene, maxDepth, params_.tlMode);
  const bool loaded = !ctx.options.cacheLoad.empty();
  size_t recordsLoaded = 0;
  if (loaded) {
    for (CacheFileEntry& e : loadCacheFile(ctx.options.cacheLoad, hash)) {
      RadianceCache& cache = engine.cacheFor(e.key);
      std::vector<float> lw, tw, bw;
      if (params_.worldFrame && !e.infos.empty()) {
        const size_t K = static_cast<size_t>(cache.coeffsPerRecord()), B = e.infos.size();
        RotateBatch rb;
        rb.order = e.key.order;
        rb.count = static_cast<int>(3 * B);
        rb.rotations.resize(9 * 3 * B);
        rb.coeffs.resize(K * 3 * B);
        for (size_t part = 0; part < 3; ++part)
          for (size_t b = 0; b < B; ++b) {
            const Frame& f = e.infos[b].frame;
            const Vec3 cols[3] = {f.t, f.b, f.n};
            for (int r = 0; r < 3; ++r)
              for (int c = 0; c < 3; ++c) rb.rotations[9 * (part * B + b) + 3 * r + c] = cols[c][r];
            const std::vector<float>& src = part == 0 ? e.lambda : part == 1 ? e.gradT : e.gradB;
            std::copy(src.begin() + K * b, src.begin() + K * (b + 1), rb.coeffs.begin() + K * (part * B + b));
          }
        std::vector<float> rot;
        backend->rotate(rb, rot);
        lw.assign(rot.begin(), rot.begin() + K * B);
        tw.assign(rot.begin() + K * B, rot.begin() + 2 * K * B);
        bw.assign(rot.begin() + 2 * K * B, rot.end());
      }
      // The file holds the final, already clamped radii: insert as they are.
      recordsLoaded += e.infos.size();
      cache.insert(e.infos, e.lambda, e.gradT, e.gradB, lw, tw, bw, false);
    }
  }

  // The primary hit of one film position (camera ray, shade point, visible emission), from the
  // camera ray's hit.
  auto primaryOf = [&](const Vec2& fpos, int pixel, uint64_t sampleSeed, const Ray& ray, const Hit& hit) {
    Primary p;
    p.filmPos = fpos;
    p.sp = engine.shadePointOf(hit, ray.d, 1, 0, sampleSeed);
    p.sp.pixel = pixel;
    if (maxDepth != 0 && !settings_.hideEmitters) {
      if (!hit.valid()) p.Le = ctx.lights.environment(ray.d);
      else if (hit.emitter >= 0) p.Le = emitted(scene, hit, -ray.d);
    }
    return p;
  };
  // Primary hits of a set of film positions (camera rays traced as coherent streams).
  auto primaries = [&](const std::vector<Vec2>& pos, const std::vector<int>& pixel, const std::vector<uint64_t>& seeds,
                       std::vector<Primary>& out) {
    out.resize(pos.size());
    parallelFor(pos.size(), 256, [&](size_t b, size_t e) {
      std::vector<Ray> rays(e - b);
      std::vector<Hit> hits(e - b);
      for (size_t i = b; i < e; ++i) rays[i - b] = camera.generate(pos[i]);
      ctx.accel.intersect(rays.data(), hits.data(), e - b, true);
      for (size_t i = b; i < e; ++i) out[i] = primaryOf(pos[i], pixel[i], seeds[i], rays[i - b], hits[i - b]);
    });
  };

  // ---- cache fill: coarse-to-fine pixel grids (skipped when a cache was loaded) ----
  auto totalRecords = [&] {
    size_t n = 0;
    for (auto& [k, c] : engine.caches()) n += c->size();
    return n;
  };
  // Per fill pass: stride, points looked up, records created, time (statistics "fill_passes").
  std::ostringstream fillPasses;
  fillPasses << "[";
  size_t edgePixels = 0;  // pixels whose quadrants the last fill pass looked up
  t0 = Clock::now();
  bool interrupted = false;
  if (!loaded) {
    std::vector<char> visited(static_cast<size_t>(W) * H, 0);
    for (int stride : kFillStrides) {
      if (interrupted) break;
      const auto passStart = Clock::now();
      const size_t recordsBefore = totalRecords();
      // The last pass looks up the centres of the four quadrants of pixels at surface edges: the
      // final pass's jittered samples then find records on every surface a pixel shows, also
      // faces that only a sub-pixel sliver of it sees, instead of creating them during shading
      // (which means shading earlier bands again; with pixel centres only, 166 of 256 bands on
      // the 512² Cornell box at 64 spp were). Inside a surface the pixel's centre is enough: a
      // jittered sample lies within 0.71 px of it and the final pass's relaxed lookup reaches
      // twice a record's radius (r_min ≥ 1.5 px). Quadrants in every pixel cost 4 lookups per
      // pixel, a quarter of the fill's time at 512²; at edges only, no band of the shipped
      // scenes is shaded again (bands_reshaded = 0, tested).
      std::vector<uint8_t> edges;
      if (stride == 1) {
        edges = surfaceEdgePixels(ctx.accel, camera, W, H);
        edgePixels = static_cast<size_t>(std::count(edges.begin(), edges.end(), uint8_t(1)));
      }
      std::vector<Vec2> pos;
      std::vector<int> pix;
      std::vector<uint64_t> seeds;
      for (int y = 0; y < H; y += stride)
        for (int x = 0; x < W; x += stride) {
          const size_t id = static_cast<size_t>(y) * W + x;
          if (stride == 1 && edges[id]) {
            for (int q = 0; q < 4; ++q) {
              pos.emplace_back(x + 0.25f + 0.5f * (q & 1), y + 0.25f + 0.5f * (q >> 1));
              pix.push_back(static_cast<int>(id));
              seeds.push_back(hashMix(seed, id, 0xF112 + q));
            }
            continue;
          }
          if (visited[id]) continue;
          visited[id] = 1;
          pos.emplace_back(x + 0.5f, y + 0.5f);
          pix.push_back(static_cast<int>(id));
          seeds.push_back(hashMix(seed, id, 0xF111));
        }
      for (size_t begin = 0; begin < pos.size(); begin += kPointsPerCall) {
        if (cancelled()) {
          interrupted = true;
          break;
        }
        const size_t end = std::min(pos.size(), begin + kPointsPerCall);
        std::vector<Primary> prim;
        primaries({pos.begin() + begin, pos.begin() + end}, {pix.begin() + begin, pix.begin() + end},
                  {seeds.begin() + begin, seeds.begin() + end}, prim);
        std::vector<ShadePoint> pts(prim.size());
        for (size_t i = 0; i < prim.size(); ++i) pts[i] = prim[i].sp;
        // Weber thresholds are relative to what the viewer sees: direct light + emission.
        std::vector<float> base(pts.size(), 0.0f);
        if (params_.adaptive) {
          parallelFor(pts.size(), 64, [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
              if (engine.technique(pts[i]) != 1) continue;
              Rng rng(pts[i].seed, 1);
              const Color d = directLight(ctx, pts[i].hit, pts[i].frame, pts[i].wo, *scene.bsdfs[pts[i].hit.bsdf], rng);
              base[i] = luminance(d + prim[i].Le);
            }
          });
        }
        engine.fill(pts, base, true);
        if (ctx.progress) ctx.progress("cache fill (stride " + std::to_string(stride) + ")", double(end), double(pos.size()));
      }
      fillPasses << (fillPasses.tellp() > 1 ? "," : "") << "{\"stride\":" << stride << ",\"points\":" << pos.size()
                 << ",\"records\":" << totalRecords() - recordsBefore << ",\"time_s\":" << since(passStart) << "}";
    }
  }
  const double fillS = since(t0);

  // ---- final pass: spp jittered samples per pixel, in bands of rows ----
  // Each band is shaded after the engine made the caches cover its points; a band that created
  // records may have changed what earlier bands would see, so bands up to the last one that
  // created records are shaded again at the end. The image is then a function of the final
  // cache alone — the same cache --cache-save writes — and rendering with --cache-load of that
  // file reproduces it exactly.
  t0 = Clock::now();
  // Bands of ≥ kSamplesPerBand samples: fewer engine calls (each a few kernel launches) at high
  // spp; ~14 MB of primaries per band.
  constexpr size_t kSamplesPerBand = 65536;
  const int rowsPerBand = std::max(1, static_cast<int>(kSamplesPerBand / std::max(1, W * spp)));
  const int bands = (H + rowsPerBand - 1) / rowsPerBand;
  std::vector<std::unique_ptr<TileFilm>> bandFilms(static_cast<size_t>(bands));
  const bool aovRecords = std::count(ctx.options.aovs.begin(), ctx.options.aovs.end(), "records") > 0;
  const bool aovRadius = std::count(ctx.options.aovs.begin(), ctx.options.aovs.end(), "radius") > 0;
  const bool aovTech = std::count(ctx.options.aovs.begin(), ctx.options.aovs.end(), "technique") > 0;
  const bool aovContrib = std::count(ctx.options.aovs.begin(), ctx.options.aovs.end(), "contributors") > 0;
  for (const std::string& a : ctx.options.aovs)
    if (a != "records" && a != "radius" && a != "technique" && a != "contributors")
      throw Error("rcache: unknown AOV '" + a + "' (known: records, radius, technique, contributors)");
  uint64_t cameraRays = 0, nanSamples = 0;
  std::atomic<uint64_t> directLightOnly{0};  // final-pass samples whose direct light skipped the BSDF ray
  // Round 0 of every pixel is [0, spp); adaptive sampling adds rounds for the pixels that need them.
  AdaptivePixels adaptive(W, H, spp, ctx.options.adaptive);
  // Shades the samples ranges[q] of the pixels q of rows [y0, y0 + pixels / W) into `tile`.
  auto shadeSamples = [&](int y0, const SampleRange* ranges, size_t pixels, TileFilm& tile) {
    std::vector<size_t> offset(pixels + 1, 0);
    // The pixels that take samples: all in a band's first round, a few in adaptive rounds (which
    // then do not walk the empty ones).
    std::vector<uint32_t> active;
    for (size_t q = 0; q < pixels; ++q) {
      offset[q + 1] = offset[q] + static_cast<size_t>(ranges[q].count());
      if (ranges[q].count() > 0) active.push_back(static_cast<uint32_t>(q));
    }
    const size_t n = offset[pixels];
    if (n == 0) return;
    std::vector<Primary> prim(n);
    std::vector<Color> direct(n, Color(0.0f));
    std::vector<int> sampleIndex(n);
    // Cached indirect light is smooth (the cache itself interpolates over ≥ r_min pixels), so
    // the samples of one pixel that land on the same surface share one lookup at the first of
    // them; direct light, emission and importance-sampled (sharp) materials stay per sample, so
    // edges, shadows and sharp reflections keep their anti-aliasing. share_pixel=false: one
    // lookup per sample. rep[i] = the sample whose lookup sample i uses. Everything per pixel
    // runs in parallel over pixels.
    std::vector<uint32_t> rep(n);
    parallelFor(active.size(), 16, [&](size_t jb, size_t je) {
      std::vector<uint32_t> pixelReps;
      uint64_t lightOnlyCount = 0;
      // One stream per sample: camera, then direct light, then (importance-sampled materials)
      // the continuation's BSDF sample, all from the pixel's low-discrepancy dimensions where
      // the sampler is ldsampler. The chunk's camera rays are traced first, as one coherent stream.
      const size_t first = offset[active[jb]], count = offset[active[je - 1] + 1] - first;
      std::vector<Rng> rngs;
      rngs.reserve(count);
      std::vector<Ray> rays(count);
      std::vector<Hit> hits(count);
      std::vector<Vec2> fpos(count);
      for (size_t j = jb; j < je; ++j) {
        const size_t q = active[j];
        const int x = static_cast<int>(q % W), y = y0 + static_cast<int>(q / W);
        for (int s = ranges[q].first; s < ranges[q].end; ++s) {
          const size_t k = offset[q] + (s - ranges[q].first) - first;
          rngs.push_back(pixelRng(seed, W, x, y, s, lowDiscrepancy));
          fpos[k] = Vec2(static_cast<float>(x), static_cast<float>(y)) + rngs[k].next2D();
          rays[k] = camera.generate(fpos[k]);
        }
      }
      ctx.accel.intersect(rays.data(), hits.data(), count, true);
      for (size_t j = jb; j < je; ++j) {
        const size_t q = active[j];
        const int x = static_cast<int>(q % W), y = y0 + static_cast<int>(q / W);
        pixelReps.clear();
        for (int s = ranges[q].first; s < ranges[q].end; ++s) {
          const size_t i = offset[q] + (s - ranges[q].first), k = i - first;
          sampleIndex[i] = s;
          Rng& rng = rngs[k];
          const uint64_t sseed = hashMix(seed, static_cast<uint64_t>(y) * W + x, 0xF1A1000000ULL + s);
          prim[i] = primaryOf(fpos[k], y * W + x, sseed, rays[k], hits[k]);
          ShadePoint& sp = prim[i].sp;
          if (sp.active && !(maxDepth >= 0 && 2 > maxDepth)) {
            const Bsdf& bsdf = *scene.bsdfs[sp.hit.bsdf];
            sp.lightSamples = params_.lightSamples;
            bool lightOnly = false;
            // Importance-sampled points: the continuation's ray doubles as the BSDF sample.
            direct[i] = engine.continuesPath(sp)
                            ? lightStrategyMis(ctx, sp.hit, sp.frame, sp.wo, bsdf, rng, params_.lightSamples)
                            : directLightCheapest(ctx, sp.hit, sp.frame, sp.wo, bsdf, rng, params_.lightSamples, &lightOnly);
            if (lightOnly) ++lightOnlyCount;
          }
          continueLowDiscrepancy(sp, rng);
          rep[i] = static_cast<uint32_t>(i);
          const bool cached = sp.active && engine.technique(sp) == 1;
          if (params_.sharePixel && cached) {
            for (uint32_t j : pixelReps) {
              const ShadePoint& o = prim[j].sp;
              if (o.hit.bsdf == sp.hit.bsdf && o.hit.mesh == sp.hit.mesh && o.hit.sphere == sp.hit.sphere &&
                  glm::dot(o.frame.n, sp.frame.n) > 0.995f) {
                rep[i] = j;
                break;
              }
            }
          }
          if (rep[i] == i && cached) pixelReps.push_back(static_cast<uint32_t>(i));
        }
      }
      directLightOnly += lightOnlyCount;
    });
    cameraRays += n;
    // Representatives in sample order (the order is what makes the image independent of threads).
    std::vector<size_t> slot(n, 0);
    std::vector<ShadePoint> repPts;
    for (size_t i = 0; i < n; ++i)
      if (rep[i] == i) {
        slot[i] = repPts.size();
        repPts.push_back(prim[i].sp);
      }
    std::vector<Color> repInd;
    std::vector<LookupAov> repAov;
    engine.indirect(repPts, repInd, &repAov, kFinalRelaxedScale);
    for (size_t i = 0; i < n; ++i) {
      const ShadePoint& sp = prim[i].sp;
      const LookupAov& la = repAov[slot[rep[i]]];
      const Bsdf* bsdf = sp.active ? scene.bsdfs[sp.hit.bsdf].get() : nullptr;
      const Color tint = bsdf && bsdf->tinted() ? bsdf->tint(sp.hit.uv, sp.wo) : Color(1.0f);  // Bsdf::tint
      const Color L = prim[i].Le + tint * (direct[i] + repInd[slot[rep[i]]]);
      const int px = sp.pixel % W, py = sp.pixel / W;
      if (isFinite(L)) {
        tile.splat(prim[i].filmPos, L);
        adaptive.add(static_cast<size_t>(sp.pixel), sampleIndex[i], L);
      } else {
        ++nanSamples;
      }
      if (aovRadius) tile.addAov("radius", px, py, Color(la.meanA, la.meanRadiusPx, 0.0f));
      if (aovContrib) tile.addAov("contributors", px, py, Color(float(la.contributors)));
      if (aovTech) {
        // red: BSDF sampling, green: irradiance cache (diffuse), blue: radiance cache (glossy)
        Color c(0.0f);
        const int t = engine.technique(sp);
        if (t == 2) c = Color(1, 0, 0);
        else if (t == 1) {
          const auto& plan = tables.plans()[sp.hit.bsdf];
          c = plan.technique == kTechniqueIrradianceCache ? Color(0, 1, 0) : Color(0, 0, 1);
        }
        tile.addAov("technique", px, py, c);
      }
    }
  };
  // A band's first spp samples per pixel (adaptive rounds come after all bands).
  auto renderBand = [&](int band) {
    const int y0 = band * rowsPerBand, y1 = std::min(H, y0 + rowsPerBand);
    const size_t begin = static_cast<size_t>(y0) * W, end = static_cast<size_t>(y1) * W;
    auto tile = std::make_unique<TileFilm>(film.makeTile(0, y0, W, y1));
    adaptive.restart(begin, end);
    shadeSamples(y0, adaptive.ranges().data() + begin, end - begin, *tile);
    bandFilms[static_cast<size_t>(band)] = std::move(tile);
  };
  // A band shaded before records were created elsewhere may have missed them; it is shaded again
  // until every band saw the final caches (usually one extra round over the bands up to the last
  // one that created records, often none). Rounds are capped: records only grow and a reshaded
  // band finds its points covered, so a third round has not been seen; the cap only bounds time.
  std::vector<size_t> shadedWith(static_cast<size_t>(bands), 0);  // record count when last shaded
  int reshaded = 0;
  for (int round = 0; round < 4 && !interrupted; ++round) {
    bool any = false;
    for (int band = 0; band < bands && !interrupted; ++band) {
      if (round > 0 && shadedWith[static_cast<size_t>(band)] == totalRecords()) continue;
      if (cancelled()) {
        interrupted = true;
        break;
      }
      renderBand(band);
      shadedWith[static_cast<size_t>(band)] = totalRecords();
      if (round > 0) ++reshaded;
      any = true;
      if (ctx.progress && round == 0) ctx.progress("render", double(band + 1), double(bands));
    }
    if (!any) break;
  }
  // Adaptive sampling: rounds over the bands that hold pixels needing more samples. Should a
  // round create records (a new sample position found no record even with the relaxed lookup),
  // every band is shaded again with the final caches and the rounds start over, once.
  // The rounds' tiles are merged as they finish into one film of their own (a tile per run of
  // rows and round, up to 8 MB each at 512², held until the end made adaptive renders' peak
  // memory grow by 100+ MB); it is dropped if the rounds start over.
  std::unique_ptr<Film> adaptiveFilm;
  for (int attempt = 0; attempt < 2 && !interrupted; ++attempt) {
    const size_t recordsBefore = totalRecords();
    adaptiveFilm.reset();
    if (ctx.options.adaptive.enabled()) adaptiveFilm = std::make_unique<Film>(scene.film, W, H);
    for (int round = 1; !interrupted && adaptive.nextRound(); ++round) {
      // Runs of rows holding ≈ kSamplesPerBand of the round's samples (few pixels take more, so
      // one engine call spans many rows and its kernel launches stay few).
      const SampleRange* r = adaptive.ranges().data();
      // Per row: samples in this round and the columns that take them.
      std::vector<size_t> rowSamples(static_cast<size_t>(H), 0);
      std::vector<int> rowX0(static_cast<size_t>(H), W), rowX1(static_cast<size_t>(H), 0);
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
          const int c = r[static_cast<size_t>(y) * W + x].count();
          if (c <= 0) continue;
          rowSamples[static_cast<size_t>(y)] += static_cast<size_t>(c);
          rowX0[static_cast<size_t>(y)] = std::min(rowX0[static_cast<size_t>(y)], x);
          rowX1[static_cast<size_t>(y)] = std::max(rowX1[static_cast<size_t>(y)], x + 1);
        }
      // Runs of rows with samples (a gap of kRunGapRows empty rows ends one), shaded into a tile
      // just covering their pixels: late rounds refine a few hundred pixels, and a tile spanning
      // every row between them (zeroed, then merged) cost more than shading them.
      constexpr int kRunGapRows = 8;
      for (int y0 = 0; y0 < H && !interrupted;) {
        while (y0 < H && rowSamples[static_cast<size_t>(y0)] == 0) ++y0;
        if (y0 >= H) break;
        size_t samples = 0;
        int y1 = y0, last = y0, x0 = W, x1 = 0;
        while (y1 < H) {
          const size_t row = rowSamples[static_cast<size_t>(y1)];
          if (row == 0) {
            if (y1 - last >= kRunGapRows) break;
            ++y1;
            continue;
          }
          if (samples > 0 && samples + row > kSamplesPerBand) break;  // a row alone may exceed it
          samples += row;
          x0 = std::min(x0, rowX0[static_cast<size_t>(y1)]);
          x1 = std::max(x1, rowX1[static_cast<size_t>(y1)]);
          last = y1++;
        }
        y1 = last + 1;
        if (cancelled()) {
          interrupted = true;
          break;
        }
        const size_t begin = static_cast<size_t>(y0) * W, end = static_cast<size_t>(y1) * W;
        auto tile = std::make_unique<TileFilm>(film.makeTile(x0, y0, x1, y1));
        shadeSamples(y0, r + begin, end - begin, *tile);
        adaptiveFilm->merge(*tile);
        if (ctx.progress) ctx.progress("render (adaptive " + std::to_string(round) + ")", double(y1), double(H));
        y0 = y1;
      }
    }
    if (interrupted || totalRecords() == recordsBefore) break;
    for (int band = 0; band < bands; ++band) renderBand(band);
    reshaded += bands;
  }
  for (auto& t : bandFilms)
    if (t) film.merge(*t);
  if (adaptiveFilm) film.add(*adaptiveFilm);
  const double finalS = since(t0);

  Image img = film.develop();
  if (aovRecords) {
    std::vector<Color> layer(static_cast<size_t>(W) * H, Color(0.0f));
    for (int p : engine.recordPixels())
      if (p >= 0 && p < W * H) layer[static_cast<size_t>(p)] += Color(1.0f);
    img.aovs["records"] = layer;
  }

  if (!ctx.options.cacheSave.empty() && !interrupted) {
    std::vector<CacheFileEntry> entries;
    for (auto& [key, cache] : engine.caches()) {
      CacheFileEntry e;
      e.key = key;
      cache->snapshot(e.infos, e.lambda, e.gradT, e.gradB);
      entries.push_back(std::move(e));
    }
    saveCacheFile(ctx.options.cacheSave, hash, entries);
  }

  // ---- statistics ----
  EngineStats& es = engine.stats();
  const double total = since(tStart);
  stats.set("time_s", total);
  stats.set("time_brdf_tables_s", tablesS);
  stats.set("time_cache_fill_s", fillS);
  stats.set("time_final_pass_s", finalS);
  fillPasses << "]";
  stats.setJson("fill_passes", fillPasses.str());
  stats.set("fill_edge_pixels_fraction", double(edgePixels) / (double(W) * H));
  const double leaf = es.projection_s + es.interpolation_s + es.dot_s;
  stats.set("time_sampling_s", std::max(0.0, fillS + finalS - leaf - es.adaptive_s));
  stats.set("time_projection_s", es.projection_s);
  stats.set("time_interpolation_s", es.interpolation_s);
  stats.set("time_dot_s", es.dot_s);
  stats.set("time_adaptive_check_s", es.adaptive_s);
  size_t records = 0, glossyRecords = 0, level0 = 0;
  std::ostringstream cj;
  cj << "[";
  bool first = true;
  for (auto& [key, cache] : engine.caches()) {
    records += cache->size();
    if (key.order > 3) glossyRecords += cache->size();
    if (key.level == 0) level0 += cache->size();
    cj << (first ? "" : ",") << "{\"level\":" << key.level << ",\"depth\":" << key.depth << ",\"order\":" << key.order
       << ",\"records\":" << cache->size() << "}";
    first = false;
  }
  cj << "]";
  stats.set("records", double(records));
  stats.set("records_primary", double(level0));
  stats.set("records_loaded", double(recordsLoaded));
  stats.set("records_glossy", double(glossyRecords));
  stats.setJson("caches", cj.str());
  stats.set("rays_record", double(es.recordRays.load()));
  stats.set("rays_camera", double(cameraRays));
  reportAdaptiveSampling(stats, ctx.options.adaptive, spp, adaptive.totalSamples(), adaptive.pixelsAboveSpp(),
                         adaptive.maxSamples(), double(W) * H);
  stats.set("rays_path", double(es.pathRays.load()));
  stats.set("rays_total", double(ctx.accel.raysTraced()));
  // "rays" and "rays_per_s" carry the same meaning as in the path tracer's statistics.
  stats.set("rays", double(ctx.accel.raysTraced()));
  stats.set("rays_per_s", total > 0 ? double(ctx.accel.raysTraced()) / total : 0.0);
  stats.set("lookups", double(es.lookups.load()));
  stats.set("records_per_lookup", es.lookups ? double(es.contributions.load()) / double(es.lookups.load()) : 0.0);
  stats.set("adaptive_shrinks", double(es.adaptiveShrinks.load()));
  stats.set("samples_dropped_nan", double(es.droppedSamples.load() + nanSamples));
  stats.set("bands_reshaded", double(reshaded));
  stats.set("direct_light_only_fraction", cameraRays ? double(directLightOnly.load()) / double(cameraRays) : 0.0);
  const KernelTimes& kt = backend->times();
  stats.set("kernel_project_s", kt.project_s);
  stats.set("kernel_rotate_s", kt.rotate_s);
  stats.set("kernel_interpolate_s", kt.interpolate_s);
  stats.set("kernel_brdf_dot_s", kt.brdfDot_s);
  stats.set("kernel_programs", kt.programs);
  stats.set("kernel_programs_cached", kt.programsFromBinaryCache);
  stats.setText("device", backend->deviceName());
  stats.setText("sampler", lowDiscrepancy ? "ldsampler" : "independent");
  stats.setText("interpolation_frame", params_.autoFrame ? "auto" : params_.worldFrame ? "world" : "record");
  stats.set("lookups_record_frame", double(es.recordFrameLookups.load()));
  stats.set("lookups_relaxed", double(es.relaxedLookups.load()));
  stats.set("lookups_lambertian", double(es.lambertianLookups.load()));
  stats.setText("mode", params_.tlMode ? "tl (Tabellion-Lamorlette dominant direction)" : "radiance");
  stats.setJson("materials", tables.materialsJson());
  std::string skipped;
  bool anyGlossy = false, anyCached = false;
  for (const auto& p : tables.plans()) {
    anyGlossy |= p.technique == kTechniqueRadianceCache;
    anyCached |= p.tableIndex >= 0;
  }
  if (!anyGlossy) skipped += "no glossy material: no glossy radiance cache, no glossy BRDF tables; ";
  if (!anyCached) skipped += "no cached material: no BRDF tables, no records; ";
  if (loaded) skipped += "cache fill passes (cache loaded from " + ctx.options.cacheLoad + "); ";
  stats.setText("skipped", skipped.empty() ? "nothing" : skipped);
  if (interrupted) stats.set("interrupted", 1.0);
  return img;
}

}  // namespace

std::unique_ptr<Integrator> makeRcacheIntegrator(const IntegratorSettings& settings) {
  return std::make_unique<RcacheIntegrator>(settings);
}

}  // namespace rc
