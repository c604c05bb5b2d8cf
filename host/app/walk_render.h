#pragma once
// Walk-throughs: `rcache SCENE.xml --frames N --camera-path keys.json` renders N frames along the
// camera path (render/camera_path.h) into NAME_0000.exr, NAME_0001.exr, ... with a progress bar
// over the frames. With rcache, frames share one cache: frame i loads the records of frames < i
// and its fill adds records only where none serves the new view (--cache-reuse semantics; records
// keep the radius clamps of the view that made them, see below), then saves the
// grown cache for frame i+1. --fresh-frames renders every frame from an empty cache instead (for
// comparison). Frame f renders with seed --seed + f. Per frame: time, fill time, records reused
// (loaded), added and too coarse (passed over).
// The pilot (cache/path_fallback.h): the shared cache is a saved cache file, which the pilot does
// not consider, so the walk asks it for its first frame; where it path-traces, every frame renders
// on its own (as with --fresh-frames) unless --cache-load or --cache-save asks for a cache.
// Radius clamps and reuse: a record's radius is clamped to [r_min, r_max] footprints of a *sensor*
// pixel (render/camera.h: the same with or without a crop window, so tiles and frames of one view
// agree) at its distance from the camera of the frame that made it, and it keeps that radius when
// later frames reuse it — the clamped radius is a property of the record (world units, stored in
// the cache file), not of the view looking at it, so every frame interpolates the same record the
// same way and the cache does not flicker. A later frame adds records where the reused ones do
// not pass the weight test at its points (newly visible surfaces, and where neighbour clamping of
// its new records shrank old radii), and where a reused record is too coarse for it: a camera
// about twice as close as the record's maker passes over the record and makes finer ones, while
// the record stays for the farther frames (cache/view_refinement.h).
#include <atomic>
#include <string>

#include "app/cli_args.h"
#include "app/progress_bar.h"
#include "cache/rcache_integrator.h"
#include "render/integrator.h"

namespace rc {

struct WalkJob {
  const RenderArgs& args;
  std::string output;  // NAME.ext: frames go to NAME_0000.ext, ...
  Scene& scene;        // the camera is moved frame by frame; ctx.scene refers to it
  const RenderContext& ctx;
  Integrator& integrator;
  RcacheIntegrator* rcache;  // the same integrator when it is rcache (its cache files), else null
  ProgressBar& bar;
};

// The output of frame `frame`: "dir/name_0007.exr" for "dir/name.exr".
std::string frameOutputPath(const std::string& output, int frame);

// Renders every frame; returns the statistics (a "frames" list among them). Stops after the
// frame that was interrupted (ctx.cancel).
RenderStats renderWalk(const WalkJob& job);

}  // namespace rc
