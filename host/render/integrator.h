#pragma once
// What every integrator gets and gives: the render context in, a film and statistics out.
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/math.h"
#include "geometry/accel.h"
#include "render/adaptive_sampling.h"
#include "scene/scene.h"

namespace rc {

class LightSampler;  // render/light_sampler.h
class Film;          // render/film.h

struct RenderOptions {
  int spp = 0;               // 0 = scene's sample_count
  uint64_t seed = 0;         // added to the scene sampler's seed
  std::string sampler;       // "" = the scene's <sampler>; else independent | ldsampler
  AdaptiveSettings adaptive; // --adaptive T, --max-spp N (off by default)
  std::vector<std::string> aovs;  // requested AOV names (integrator-specific)
};

struct PhaseCpu;

// Named statistics, printed in insertion order and written to --stats JSON.
// Numbers are doubles; text values (device, technique) strings; nested lists are JSON snippets.
struct RenderStats {
  std::vector<std::pair<std::string, double>> numbers;
  std::vector<std::pair<std::string, std::string>> texts;
  std::vector<std::pair<std::string, std::string>> json;  // key → raw JSON value (arrays/objects)
  void set(const std::string& key, double value);
  void setText(const std::string& key, const std::string& value);
  void setJson(const std::string& key, const std::string& rawJson);
  // A phase's CPU seconds by where they ran (core/phase_cpu.h): cpu_<phase>_serial_s, _loops_s,
  // _loops_span_at_2_s, _other_threads_s, <phase>_parallel_loops and <phase>_control_thread_sleeps.
  void setPhaseCpu(const std::string& phase, const PhaseCpu& cpu);
  double get(const std::string& key, double fallback = 0.0) const;
  std::string text(const std::string& key) const;  // "" when not set
};

// Linear RGB image plus optional named AOV layers, all width×height, row-major, top row first.
struct Image {
  int width = 0, height = 0;
  std::vector<Color> pixels;
  std::map<std::string, std::vector<Color>> aovs;
};

struct RenderContext {
  const Scene& scene;
  const Accel& accel;
  const LightSampler& lights;
  RenderOptions options;
  std::atomic<bool>* cancel = nullptr;  // set by SIGINT: stop early, keep what is done
  // Progress reporting: called with (phase name, done, total); the CLI draws the bar.
  std::function<void(const std::string&, double, double)> progress;
};

// One render of an integrator as passes of samples: made by Integrator::beginPasses, which does
// the work done once per render (rcache: BRDF tables, pilot, cache fill). A render is one pass
// (Integrator::render); --time renders as many as its budget allows (render/progressive.h).
class PassRender {
 public:
  virtual ~PassRender() = default;
  // Samples per pixel of one pass: RenderOptions::spp, else the scene's sample_count.
  virtual int passSpp() const = 0;
  // Adds samples [firstSample, firstSample + passSpp()) of every pixel's streams to `film` (the
  // scene's film). Honours ctx.cancel: stops early, keeping what is done in `film` (pixels not yet
  // rendered get nothing), and returns false.
  virtual bool addPass(Film& film, int firstSample) = 0;
  // The image of `film`, which holds `passes` passes (a cut one counted), with the integrator's
  // extra layers, and its statistics. `stopped`: the render was stopped (SIGINT) rather than
  // finished — stats "interrupted" = 1, and nothing that needs a finished render (rcache's cache
  // save) is done. A pass the --time budget cut and the driver dropped does not count.
  virtual Image finish(const Film& film, int passes, bool stopped, RenderStats& stats) = 0;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string name() const = 0;
  // `ctx` outlives the returned passes.
  virtual std::unique_ptr<PassRender> beginPasses(const RenderContext& ctx, RenderStats& stats) = 0;
  // Renders the whole image: one pass. Honours ctx.cancel (a partial image, pixels not yet
  // rendered black, and stats "interrupted" = 1).
  Image render(const RenderContext& ctx, RenderStats& stats);
};

}  // namespace rc
