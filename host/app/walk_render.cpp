#include "app/walk_render.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "core/error.h"
#include "core/json_writer.h"
#include "core/timing.h"
#include "image/image_file.h"
#include "render/camera_path.h"
#include "render/image_io.h"

namespace rc {

namespace {

// "dir/name.exr" → {"dir/name", ".exr"}; no extension → {path, ""}.
std::pair<std::string, std::string> splitExtension(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {path, ""};
  return {path.substr(0, dot), path.substr(dot)};
}

// The cache the frames share: --cache-save F if given (it then holds every frame's records at the
// end), else a file beside the frames that is removed afterwards.
std::string sharedCachePath(const WalkJob& job) {
  if (!job.args.cacheSave.empty()) return job.args.cacheSave;
  return splitExtension(job.output).first + "_walk.rcc";
}

// Whether the rcache integrator's pilot path-traces frame `frame` (cache/path_fallback.h): asked
// on a one-pixel crop at 1 spp, since the pilot samples the whole sensor whatever the crop. The
// shared cache is a cache file the walk saves, which the pilot would not consider, so the walk
// asks first. Not the fill's predicted payoff (cache/fill_payoff.h): it weighs one image's fill
// against one image's samples, and the walk's frames share theirs.
bool pilotPathTraces(const WalkJob& job, const Camera& camera, int frame) {
  const FilmSettings film = job.scene.film;
  job.scene.camera = camera;
  job.scene.film.cropWidth = job.scene.film.cropHeight = 1;
  RenderContext ctx = job.ctx;
  ctx.options.seed += static_cast<uint64_t>(frame);
  ctx.options.spp = 1;
  const bool payoff = job.rcache && job.rcache->fillPayoff();
  if (job.rcache) {
    job.rcache->setCacheFiles({});
    job.rcache->setFillPayoff(false);
  }
  ctx.progress = nullptr;
  RenderStats stats;
  auto restore = [&] {
    job.scene.film = film;
    if (job.rcache) job.rcache->setFillPayoff(payoff);
  };
  try {
    job.integrator.render(ctx, stats);
  } catch (...) {
    restore();
    throw;
  }
  restore();
  return stats.text("fallback").rfind("path traced", 0) == 0;
}

}  // namespace

std::string frameOutputPath(const std::string& output, int frame) {
  char num[16];
  std::snprintf(num, sizeof num, "_%04d", frame);
  const auto [stem, ext] = splitExtension(output);
  return stem + num + ext;
}

RenderStats renderWalk(const WalkJob& job) {
  const RenderArgs& ra = job.args;
  const std::vector<CameraKey> keys = readCameraPath(ra.cameraPath);
  const Camera base = job.scene.camera;
  const auto start = SteadyClock::now();
  const int first = ra.firstFrame, end = ra.endFrame > 0 ? ra.endFrame : ra.frames;
  // A walk whose first frame caching cannot pay renders every frame on its own (each deciding as
  // a still does) instead of forcing a shared cache on it — unless a cache file was asked for.
  const bool rcache = job.rcache && !ra.freshFrames;
  const bool pathTraced = rcache && ra.cacheLoad.empty() && ra.cacheSave.empty() && first < end &&
                          pilotPathTraces(job, cameraOfFrame(base, keys, first, ra.frames), first);
  const bool shareCache = rcache && !pathTraced;
  const std::string cachePath = shareCache ? sharedCachePath(job) : std::string();

  JsonWriter frames;
  frames.beginArray();
  RenderStats total;
  double fillSum = 0.0, reused = 0.0, added = 0.0;
  int rendered = 0;
  bool interrupted = false;
  for (int f = first; f < end && !interrupted; ++f) {
    job.scene.camera = cameraOfFrame(base, keys, f, ra.frames);
    RenderContext ctx = job.ctx;
    // Frame f draws with seed + f: noise that stays put on the screen while the camera moves
    // reads as a dirty lens; independent frames let the eye average it away.
    ctx.options.seed += static_cast<uint64_t>(f);
    // One bar over the frames: a frame's phases advance it within the frame.
    ctx.progress = [&job, f, n = ra.frames](const std::string&, double done, double work) {
      job.bar.update("frames", f + std::min(0.999, work > 0.0 ? done / work : 0.0), n);
    };
    if (shareCache) {
      const std::string load = f == first ? ra.cacheLoad : cachePath;
      job.rcache->setCacheFiles({cachePath, load, !load.empty()});
    }
    RenderStats stats;
    const auto t0 = SteadyClock::now();
    const Image image = job.integrator.render(ctx, stats);
    const double frameS = secondsSince(t0);
    const std::string out = frameOutputPath(job.output, f);
    writeImage(image, out);
    // The frame is written; a failed save of the shared cache stops the walk (the next frame would
    // otherwise load a stale cache or none).
    const std::string cacheError = stats.text("cache_save_error");
    if (!cacheError.empty()) throw Error(cacheError);
    interrupted = stats.get("interrupted") > 0.0 || (ctx.cancel && ctx.cancel->load());
    const double fillS = stats.get("time_cache_fill_s");
    fillSum += fillS;
    reused += stats.get("records_loaded");
    added += stats.get("records_added");
    ++rendered;
    frames.beginObject()
        .field("frame", f)
        .field("output", out)
        .field("time_s", frameS)
        .field("time_cache_fill_s", fillS)
        .field("records", stats.get("records"))
        .field("records_reused", stats.get("records_loaded"))
        .field("records_added", stats.get("records_added"))
        .field("records_too_coarse", stats.get("records_too_coarse"))
        .field("fallback", stats.text("fallback"))
        .endObject();
    job.bar.update("frames", f + 1, ra.frames);
    if (f == 0) total.setText("integrator", job.integrator.name());
  }
  frames.endArray();
  job.bar.finish();
  if (shareCache && ra.cacheSave.empty()) std::remove(cachePath.c_str());
  total.set("frames", rendered);
  total.setText("cache_across_frames", shareCache ? "shared" : pathTraced ? "none: the first frame's pilot path-traces" : "none");
  total.set("time_frames_s", secondsSince(start));
  total.set("time_per_frame_s", rendered > 0 ? secondsSince(start) / rendered : 0.0);
  total.set("time_cache_fill_s", fillSum);
  total.set("records_reused", reused);
  total.set("records_added", added);
  total.setJson("frames_list", frames.str());
  if (interrupted) total.set("interrupted", 1);
  return total;
}

}  // namespace rc
