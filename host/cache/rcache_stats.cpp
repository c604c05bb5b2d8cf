#include "cache/rcache_stats.h"

#include <algorithm>
#include <cmath>

#include "cl/sh_backend.h"
#include "core/json_writer.h"

namespace rc {

void FinalPassTotals::add(const FinalPass& pass, const AdaptivePixels& adaptive) {
  cameraRays += pass.cameraRays();
  nanSamples += pass.nanSamples();
  directLightOnly += pass.directLightOnly();
  lobeSplitSamples += pass.lobeSplitSamples();
  bandsReshaded += pass.bandsReshaded();
  samples += adaptive.totalSamples();
  pixelsAboveSpp += adaptive.pixelsAboveSpp();
  maxPixelSamples = std::max(maxPixelSamples, adaptive.maxSamples());
}

namespace {

void reportTimes(const RcacheRun& run, const RcacheReport& r, RenderStats& stats) {
  const EngineStats& es = run.engine.stats();
  const double fillS = r.fill.seconds;
  stats.set("time_s", r.totalS);
  stats.set("time_brdf_tables_s", r.tablesS);
  stats.set("time_cache_fill_s", fillS);
  stats.set("time_final_pass_s", r.finalS);
  stats.setJson("fill_passes", r.fill.passesJson);
  stats.set("fill_edge_pixels_fraction", double(r.fill.edgePixels) / (double(run.width) * run.height));
  const double leaf = es.projection_s + es.interpolation_s + es.dot_s;
  stats.set("time_sampling_s", std::max(0.0, fillS + r.finalS - leaf - es.adaptive_s));
  stats.set("time_projection_s", es.projection_s);
  stats.set("time_interpolation_s", es.interpolation_s);
  stats.set("time_dot_s", es.dot_s);
  stats.set("time_adaptive_check_s", es.adaptive_s);
  stats.setPhaseCpu("cache_fill", r.fill.cpu);
  stats.setPhaseCpu("final_pass", r.passes.cpu);
}

void reportRecords(const RcacheRun& run, const RcacheReport& r, RenderStats& stats) {
  size_t records = 0, glossyRecords = 0, level0 = 0;
  JsonWriter caches;
  caches.beginArray();
  for (auto& [key, cache] : run.engine.caches()) {
    records += cache->size();
    if (key.order > 3) glossyRecords += cache->size();
    if (key.level == 0) level0 += cache->size();
    caches.beginObject()
        .field("level", key.level)
        .field("depth", key.depth)
        .field("order", key.order)
        .field("records", cache->size())
        .endObject();
  }
  caches.endArray();
  stats.set("records", double(records));
  stats.set("records_primary", double(level0));
  stats.set("records_loaded", double(r.recordsLoaded));
  stats.set("records_added", double(records) - double(r.recordsLoaded));
  stats.set("records_glossy", double(glossyRecords));
  stats.setJson("caches", caches.str());
}

void reportRaysAndLookups(const RcacheRun& run, const RcacheReport& r, RenderStats& stats) {
  const EngineStats& es = run.engine.stats();
  const Accel& accel = run.ctx.accel;
  const uint64_t cameraRays = r.passes.cameraRays;
  stats.set("rays_record", double(es.recordRays.load()));
  stats.set("rays_camera", double(cameraRays));
  reportAdaptiveSampling(stats, run.ctx.options.adaptive, run.spp, r.passes.samples, r.passes.pixelsAboveSpp,
                         r.passes.maxPixelSamples, double(run.width) * run.height);
  stats.set("rays_path", double(es.pathRays.load()));
  stats.set("rays_total", double(accel.raysTraced()));
  // "rays" and "rays_per_s" carry the same meaning as in the path tracer's statistics.
  stats.set("rays", double(accel.raysTraced()));
  stats.set("rays_per_s", r.totalS > 0 ? double(accel.raysTraced()) / r.totalS : 0.0);
  stats.set("lookups", double(es.lookups.load()));
  stats.set("records_per_lookup", es.lookups ? double(es.contributions.load()) / double(es.lookups.load()) : 0.0);
  stats.set("adaptive_shrinks", double(es.adaptiveShrinks.load()));
  stats.set("samples_dropped_nan", double(es.droppedSamples.load() + r.passes.nanSamples));
  stats.set("bands_reshaded", double(r.passes.bandsReshaded));
  stats.set("direct_light_only_fraction", cameraRays ? double(r.passes.directLightOnly) / double(cameraRays) : 0.0);
  stats.set("lobe_split_fraction", cameraRays ? double(r.passes.lobeSplitSamples) / double(cameraRays) : 0.0);
}

void reportKernels(const RcacheRun& run, RenderStats& stats) {
  const ShBackend& backend = run.backend;
  const KernelTimes& kt = backend.times();
  stats.set("kernel_project_s", kt.project_s);
  stats.set("kernel_rotate_s", kt.rotate_s);
  stats.set("kernel_interpolate_s", kt.interpolate_s);
  stats.set("kernel_brdf_dot_s", kt.brdfDot_s);
  stats.set("kernel_programs", kt.programs);
  stats.set("kernel_programs_cached", kt.programsFromBinaryCache);
  stats.setText("device", backend.deviceName());
}

void reportModes(const RcacheRun& run, RenderStats& stats) {
  const EngineStats& es = run.engine.stats();
  const RcacheParams& p = run.params;
  stats.setText("sampler", run.lowDiscrepancy ? "ldsampler" : "independent");
  stats.setText("interpolation_frame", p.autoFrame ? "auto" : p.worldFrame ? "world" : "record");
  stats.set("lookups_record_frame", double(es.recordFrameLookups.load()));
  stats.set("lookups_relaxed", double(es.relaxedLookups.load()));
  stats.set("lookups_lambertian", double(es.lambertianLookups.load()));
  // The record settings this render used (cache/budget_params.h: they follow the spp).
  stats.set("record_rays", double(p.rays));
  stats.set("secondary_record_rays", double(p.secondaryRays));
  stats.set("record_a", p.a);
  stats.set("record_rmin", p.rMinPx);
  stats.set("record_rmax", p.rMaxPx);
  stats.setText("mode", p.tlMode ? "tl (Tabellion-Lamorlette dominant direction)" : "radiance");
  stats.setJson("materials", run.tables.materialsJson());
  // The light split (cache/light_split.h): τ and the power fractions on each side.
  const LightSplitSummary& split = run.engine.lightSplit().summary();
  if (split.environmentCached) {
    stats.setText("env_cache", std::isfinite(split.threshold) ? "split" : "whole environment cached");
    if (std::isfinite(split.threshold)) stats.set("env_threshold", split.threshold);
    stats.set("env_cached_fraction", split.cachedFraction);
    stats.set("env_sampled_fraction", split.sampledFraction);
  } else {
    stats.setText("env_cache", "off (" + split.reason + ")");
  }
  stats.setText("area_cache", split.areaCached ? "area emitters cached" : "off");
}

// What the render did not do, and why.
std::string skippedWork(const RcacheRun& run) {
  std::string skipped;
  bool anyGlossy = false, anyCached = false;
  for (const auto& p : run.tables.plans()) {
    anyGlossy |= p.technique == Technique::RadianceCache;
    anyCached |= p.tableIndex >= 0;
  }
  if (!anyGlossy) skipped += "no glossy material: no glossy radiance cache, no glossy BRDF tables; ";
  if (!anyCached) skipped += "no cached material: no BRDF tables, no records; ";
  if (!run.files.load.empty() && !run.files.reuse)
    skipped += "cache fill passes (cache loaded from " + run.files.load + "); ";
  return skipped.empty() ? "nothing" : skipped;
}

}  // namespace

void reportRcacheStats(const RcacheRun& run, const RcacheReport& report, RenderStats& stats) {
  reportTimes(run, report, stats);
  reportRecords(run, report, stats);
  reportRaysAndLookups(run, report, stats);
  reportKernels(run, stats);
  reportModes(run, stats);
  stats.setText("skipped", skippedWork(run));
  if (report.interrupted) stats.set("interrupted", 1.0);
}

}  // namespace rc
