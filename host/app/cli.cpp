#include "app/cli.h"

#include <signal.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "app/cli_args.h"
#include "app/cache_command.h"
#include "app/diff_command.h"
#include "app/integrator_registry.h"
#include "app/output_checks.h"
#include "app/progress_bar.h"
#include "app/stats_report.h"
#include "app/walk_render.h"
#include "cache/rcache_integrator.h"
#include "cl/cl_runtime.h"
#include "cl/sh_backend.h"
#include "cl/verify.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/parallel.h"
#include "core/phase_cpu.h"
#include "core/timing.h"
#include "geometry/accel.h"
#include "render/image_io.h"
#include "render/light_sampler.h"
#include "render/progressive.h"
#include "scene/param_reader.h"
#include "scene/scene_loader.h"

namespace rc {

namespace {

std::atomic<bool> gCancel{false};
std::atomic<int> gSignal{0};

// SIGINT and SIGTERM alike: the first stops the render early (the partial image is still written,
// and a write in progress finishes); a second one means leave now, removing any temporary file.
extern "C" void onStopSignal(int sig) {
  int none = 0;
  gSignal.compare_exchange_strong(none, sig);
  if (gCancel.exchange(true)) {
    removeRegisteredTemporaries();
    std::_Exit(128 + gSignal.load());
  }
}

void installSignalHandlers() {
  struct sigaction sa {};
  sa.sa_handler = onStopSignal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  // A file-size limit (ulimit -f) is a full disk by another name: let write(2) fail with EFBIG
  // and report it, rather than die of SIGXFSZ with a temporary left behind.
  std::signal(SIGXFSZ, SIG_IGN);
}

std::string defaultOutputPath(const std::string& scenePath) {
  const size_t slash = scenePath.find_last_of('/');
  const size_t dot = scenePath.find_last_of('.');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) return scenePath.substr(0, dot) + ".exr";
  return scenePath + ".exr";
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
// Nothing given on the command line is silently dropped: the options only rcache reads are refused
// for the others, and so is a -D naming a parameter of another integrator than the one rendering —
// unless the file declares that name with <default>, where the define substitutes its $name.
std::unique_ptr<Integrator> integratorFor(const RenderArgs& ra, const Scene& scene, const IntegratorEntry*& entry) {
  IntegratorSettings settings = scene.integrator;
  settings.type = chooseIntegrator(ra.integrator, scene);
  if (settings.type != "rcache") {
    const std::string uses = ": only with the rcache integrator (this render uses " + settings.type + ")";
    if (!ra.cacheSave.empty()) throw Error("--cache-save" + uses);
    if (!ra.cacheLoad.empty()) throw Error("--cache-load" + uses);
    if (!ra.aovs.empty()) throw Error("--aov " + ra.aovs.front() + uses);
  }
  const std::vector<std::string> paramNames = integratorParameterNames(settings.type);
  for (const auto& [name, value] : ra.defines) {
    const std::string flag = "-D " + name + "=" + value;
    if (std::find(paramNames.begin(), paramNames.end(), name) != paramNames.end()) {
      settings.props.set(name, textProperty(value));
      settings.paramWhere[name] = flag;  // a bad value is reported as the option, not the file's line
      continue;
    }
    if (scene.defaultNames.count(name)) continue;  // the file's own $name, substituted by the loader
    for (const IntegratorEntry& other : integratorEntries()) {
      const std::vector<std::string> otherNames = integratorParameterNames(other.name);
      if (std::find(otherNames.begin(), otherNames.end(), name) != otherNames.end())
        throw Error(flag + ": '" + name + "' is " + (other.name == "rcache" ? "an " : "a ") + other.name +
                    " parameter, but this render uses the " + settings.type + " integrator");
    }
    // Otherwise a scene parameter ($name) only, as in Mitsuba.
  }
  std::vector<std::string> warnings;
  auto integrator = makeIntegrator(settings, ra.lenient, settings.type == scene.integrator.type, &warnings, &entry);
  for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
  return integrator;
}

Scene loadSceneReportingWarnings(const RenderArgs& ra) {
  LoadOptions lo;
  lo.defines = ra.defines;
  lo.lenient = ra.lenient;
  std::vector<std::string> warnings;
  Scene scene = loadScene(ra.scenePath, lo, &warnings);
  for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
  return scene;
}

std::unique_ptr<ShBackend> backendFor(const RenderArgs& ra, const IntegratorEntry& entry) {
  std::unique_ptr<ShBackend> backend;
  if (entry.usesKernels) {
    std::string notice;
    backend = makeShBackend(ra.device, &notice);
    if (!notice.empty() && !ra.quiet) std::cerr << "notice: " << notice << "\n";
  }
  return backend;
}

RenderOptions renderOptionsFrom(const RenderArgs& ra) {
  RenderOptions opts;
  opts.spp = ra.spp;
  opts.sampler = ra.sampler;
  opts.adaptive.threshold = ra.adaptiveThreshold;
  opts.adaptive.maxSpp = ra.maxSpp;
  opts.seed = ra.seed;
  opts.aovs = ra.aovs;
  return opts;
}

// The options only rcache reads go to the rcache integrator itself (integratorFor refused them for
// the others). Null when the render uses another integrator.
RcacheIntegrator* handRcacheOptions(Integrator& integrator, const RenderArgs& ra, ShBackend* backend) {
  auto* rcache = dynamic_cast<RcacheIntegrator*>(&integrator);
  if (rcache) {
    rcache->setBackend(backend);
    rcache->setCacheFiles({ra.cacheSave, ra.cacheLoad, ra.cacheReuse});
  }
  return rcache;
}

void reportStats(const RenderStats& stats, const RenderArgs& ra) {
  if (!ra.quiet) printStats(stats, std::cout);
  if (!ra.statsPath.empty()) writeFileAtomically(ra.statsPath, statsToJson(stats));
}

// Seconds spent in each phase of one image render.
struct PhaseSeconds {
  double load = 0.0, bvh = 0.0, render = 0.0, write = 0.0;
  PhaseCpu renderCpu;
};

void recordImageStats(RenderStats& stats, const RenderArgs& ra, const std::string& output, const Integrator& integrator,
                      const ShBackend* backend, const Image& image, const PhaseSeconds& t) {
  stats.setText("scene", ra.scenePath);
  stats.setText("output", output);
  stats.setText("integrator", integrator.name());
  stats.setText("device", backend ? backend->deviceName() : std::string("cpu (path tracer needs no kernels)"));
  stats.set("threads", threadCount());
  if (backend && backend->kernelThreads() > 0) stats.set("kernel_threads", backend->kernelThreads());
  stats.set("width", image.width);
  stats.set("height", image.height);
  stats.set("time_load_s", t.load);
  stats.set("time_bvh_s", t.bvh);
  stats.set("time_render_s", t.render);
  stats.set("time_write_s", t.write);
  stats.setPhaseCpu("render", t.renderCpu);
}

int runRender(const std::vector<std::string>& args) {
  RenderArgs ra = parseRenderArgs(args);
  if (ra.threads > 0) setThreadCount(ra.threads);
  cl::limitCpuDeviceThreads(ra.threads);  // before any OpenCL call: the platform reads it once
  const std::string output = ra.outputPath.empty() ? defaultOutputPath(ra.scenePath) : ra.outputPath;
  checkOutputs(ra, output);
  installSignalHandlers();

  RenderStats stats;
  PhaseSeconds t;
  const auto tStart = SteadyClock::now();
  Scene scene = loadSceneReportingWarnings(ra);
  t.load = secondsSince(tStart);
  if (gCancel) return 128 + gSignal.load();  // stopped while loading: nothing rendered to keep
  applyCropFlag(ra.crop, scene.film);
  const IntegratorEntry* entry = nullptr;
  std::unique_ptr<Integrator> integrator = integratorFor(ra, scene, entry);

  const auto tBvh = SteadyClock::now();
  Accel accel(scene);
  LightSampler lights(scene);
  t.bvh = secondsSince(tBvh);

  std::unique_ptr<ShBackend> backend = backendFor(ra, *entry);
  RcacheIntegrator* rcache = handRcacheOptions(*integrator, ra, backend.get());

  ProgressBar bar(ra.quiet);
  RenderOptions opts = renderOptionsFrom(ra);
  RenderContext ctx{scene, accel, lights, opts, &gCancel,
                    [&bar](const std::string& phase, double done, double total) { bar.update(phase, done, total); }};

  if (ra.frames > 0) {
    stats = renderWalk({ra, output, scene, ctx, *integrator, rcache, bar});
    stats.setText("scene", ra.scenePath);
    stats.set("time_s", secondsSince(tStart));
    reportStats(stats, ra);
    return gCancel ? 128 + gSignal.load() : 0;
  }
  const auto tRender = SteadyClock::now();
  const PhaseCpuMeter renderCpu;
  Image image = ra.timeBudget > 0.0 ? renderProgressive(*integrator, ctx, {ra.timeBudget}, stats)
                                    : integrator->render(ctx, stats);
  t.render = secondsSince(tRender);
  t.renderCpu = renderCpu.elapsed();
  bar.finish();

  const auto tWrite = SteadyClock::now();
  writeImage(image, output);
  t.write = secondsSince(tWrite);

  recordImageStats(stats, ra, output, *integrator, backend.get(), image, t);
  // --integrator renders its name whatever the file asks for (a direct file as rcache is global
  // illumination), so the statistics name the file's integrator wherever another one rendered it.
  if (chooseIntegrator(ra.integrator, scene) != scene.integrator.type)
    stats.setText("file_integrator", scene.integrator.type);
  stats.set("time_s", secondsSince(tStart));
  if (gCancel) stats.set("interrupted", 1);
  reportStats(stats, ra);
  // A failed cache save does not cost the image: it was written above, the failure is reported now.
  const std::string cacheError = stats.text("cache_save_error");
  if (!cacheError.empty()) throw Error(cacheError);
  if (gCancel) {
    std::cerr << "interrupted: wrote the partial image to " << output << "\n";
    return 128 + gSignal.load();
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
