#include "app/cli.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "app/cli_args.h"
#include "app/diff_command.h"
#include "app/integrator_registry.h"
#include "app/progress_bar.h"
#include "app/stats_report.h"
#include "app/walk_render.h"
#include "app/cache_command.h"
#include "cl/sh_backend.h"
#include "cl/verify.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/parallel.h"
#include "core/timing.h"
#include "geometry/accel.h"
#include "image/image_file.h"
#include "image/oiio_module.h"
#include "render/image_io.h"
#include "render/light_sampler.h"
#include "scene/param_reader.h"
#include "scene/scene_loader.h"

namespace rc {

namespace {

std::atomic<bool> gCancel{false};

extern "C" void onInterrupt(int) {
  // Second Ctrl-C: the user insists, leave immediately.
  if (gCancel.exchange(true)) std::_Exit(130);
}

std::string defaultOutputPath(const std::string& scenePath) {
  const size_t slash = scenePath.find_last_of('/');
  const size_t dot = scenePath.find_last_of('.');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) return scenePath.substr(0, dot) + ".exr";
  return scenePath + ".exr";
}

// Fails before a long render rather than after it: the format must be known and the directory writable.
void checkOutputWritable(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".exr" && ext != ".png" && ext != ".hdr")
    throw Error(path + ": unsupported output format (use .exr, .png or .hdr)");
  // PNG and HDR are written through the OpenImageIO module: load it now, so that a missing module
  // is an error before the render instead of after it.
  if (ext != ".exr") oiioModule();
  const size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  if (access(dir.c_str(), W_OK) != 0) throw Error(path + ": directory '" + dir + "' is not writable");
}

bool sceneHasCachedMaterial(const Scene& scene) {
  for (const BsdfPtr& b : scene.bsdfs)
    if (b && (b->lobes() & (kLobeDiffuse | kLobeGlossy))) return true;
  return false;
}

// --integrator NAME renders NAME whatever the file says; auto renders the file's integrator, except
// that a path tracer (path, volpath, volpathmis, or no <integrator>) becomes rcache when the scene
// has a material rcache caches: the same estimate, cached.
std::string chooseIntegrator(const std::string& requested, const Scene& scene) {
  if (requested != "auto") return requested;
  const IntegratorEntry* file = findIntegrator(scene.integrator.type);
  if (file && file->pathFamily && sceneHasCachedMaterial(scene)) return "rcache";
  return scene.integrator.type;
}

// The integrator to render with (--integrator, else the file's), with the -D names that are its
// parameters applied: they override the file; other names are scene parameters only, as in Mitsuba.
std::unique_ptr<Integrator> integratorFor(const RenderArgs& ra, const Scene& scene, const IntegratorEntry*& entry) {
  IntegratorSettings settings = scene.integrator;
  settings.type = chooseIntegrator(ra.integrator, scene);
  const std::vector<std::string> paramNames = integratorParameterNames(settings.type);
  for (const auto& kv : ra.defines)
    if (std::find(paramNames.begin(), paramNames.end(), kv.first) != paramNames.end())
      settings.props.set(kv.first, textProperty(kv.second));
  std::vector<std::string> warnings;
  auto integrator = makeIntegrator(settings, ra.lenient, settings.type == scene.integrator.type, &warnings, &entry);
  for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
  return integrator;
}

int runRender(const std::vector<std::string>& args) {
  RenderArgs ra = parseRenderArgs(args);
  if (ra.threads > 0) setThreadCount(ra.threads);
  const std::string output = ra.outputPath.empty() ? defaultOutputPath(ra.scenePath) : ra.outputPath;
  checkOutputWritable(output);
  for (const std::string* p : {&ra.statsPath, &ra.cacheSave})
    if (!p->empty()) {
      const size_t slash = p->find_last_of('/');
      const std::string dir = slash == std::string::npos ? "." : p->substr(0, slash);
      if (access(dir.c_str(), W_OK) != 0) throw Error(*p + ": directory '" + dir + "' is not writable");
    }

  RenderStats stats;
  const auto tStart = SteadyClock::now();
  LoadOptions lo;
  lo.defines = ra.defines;
  lo.lenient = ra.lenient;
  std::vector<std::string> warnings;
  Scene scene = loadScene(ra.scenePath, lo, &warnings);
  for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
  applyCropFlag(ra.crop, scene.film);
  const IntegratorEntry* entry = nullptr;
  std::unique_ptr<Integrator> integrator = integratorFor(ra, scene, entry);
  const double loadS = secondsSince(tStart);

  const auto tBvh = SteadyClock::now();
  Accel accel(scene);
  LightSampler lights(scene);
  const double bvhS = secondsSince(tBvh);

  std::unique_ptr<ShBackend> backend;
  if (entry->usesKernels) {
    std::string notice;
    backend = makeShBackend(ra.device, &notice);
    if (!notice.empty() && !ra.quiet) std::cerr << "notice: " << notice << "\n";
  }

  ProgressBar bar(ra.quiet);
  RenderOptions opts;
  opts.spp = ra.spp;
  opts.sampler = ra.sampler;
  opts.adaptive.threshold = ra.adaptiveThreshold;
  opts.adaptive.maxSpp = ra.maxSpp;
  opts.seed = ra.seed;
  opts.aovs = ra.aovs;
  opts.cacheSave = ra.cacheSave;
  opts.cacheLoad = ra.cacheLoad;
  opts.cacheReuse = ra.cacheReuse;
  RenderContext ctx{scene, accel, lights, opts, backend.get(), &gCancel,
                    [&bar](const std::string& phase, double done, double total) { bar.update(phase, done, total); }};

  std::signal(SIGINT, onInterrupt);
  if (ra.frames > 0) {
    stats = renderWalk({ra, output, scene, ctx, *integrator, bar});
    std::signal(SIGINT, SIG_DFL);
    stats.setText("scene", ra.scenePath);
    stats.set("time_s", secondsSince(tStart));
    if (!ra.quiet) printStats(stats, std::cout);
    if (!ra.statsPath.empty()) writeFileAtomically(ra.statsPath, statsToJson(stats));
    return gCancel ? 130 : 0;
  }
  const auto tRender = SteadyClock::now();
  Image image = integrator->render(ctx, stats);
  const double renderS = secondsSince(tRender);
  std::signal(SIGINT, SIG_DFL);
  bar.finish();

  const auto tWrite = SteadyClock::now();
  writeImage(image, output);
  const double writeS = secondsSince(tWrite);

  stats.setText("scene", ra.scenePath);
  stats.setText("output", output);
  stats.setText("integrator", integrator->name());
  stats.setText("device", backend ? backend->deviceName() : std::string("cpu (path tracer needs no kernels)"));
  stats.set("threads", threadCount());
  stats.set("width", image.width);
  stats.set("height", image.height);
  stats.set("time_load_s", loadS);
  stats.set("time_bvh_s", bvhS);
  stats.set("time_render_s", renderS);
  stats.set("time_write_s", writeS);
  stats.set("time_s", secondsSince(tStart));
  if (gCancel) stats.set("interrupted", 1);
  if (!ra.quiet) printStats(stats, std::cout);
  if (!ra.statsPath.empty()) writeFileAtomically(ra.statsPath, statsToJson(stats));
  if (gCancel) {
    std::cerr << "interrupted: wrote the partial image to " << output << "\n";
    return 130;
  }
  return 0;
}

}  // namespace

int runCli(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.empty() || args[0] == "-h" || args[0] == "--help") {
      std::cout << usageText();
      return args.empty() ? 2 : 0;
    }
    const std::string cmd = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (cmd == "devices") {
      if (!rest.empty()) throw Error("devices: takes no arguments");
      listDevices(std::cout);
      return 0;
    }
    if (cmd == "verify") {
      const VerifyArgs v = parseVerifyArgs(rest);
      return runVerify(v.device, v.order, std::cout);
    }
    if (cmd == "diff") return runDiff(parseDiffArgs(rest), std::cout);
    if (cmd == "cache") return runCacheCommand(rest, std::cout);
    return runRender(args);
  } catch (const Error& e) {
    std::cerr << "rcache: error: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "rcache: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "rcache: internal error: " << e.what() << "\n";
    return 3;
  }
}

}  // namespace rc
