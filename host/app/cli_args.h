#pragma once
// Command-line options of `rcache SCENE.xml` (README "Command line"), parsed strictly: an unknown flag, a
// missing value or an absurd number is an rc::Error that names the flag.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "app/crop_flag.h"

namespace rc {

struct RenderArgs {
  std::string scenePath;
  std::string outputPath;                      // empty → next to the scene: SCENE.exr
  std::map<std::string, std::string> defines;  // -D name=value
  std::string integrator = "auto";             // auto | rcache | path
  int spp = 0;                                 // 0 → scene's sample_count
  std::string device;                          // "" → RC_DEVICE or auto
  int threads = 0;                             // 0 → all hardware threads
  uint64_t seed = 0;
  std::string sampler;                         // "" → scene's <sampler>
  float adaptiveThreshold = 0.0f;              // --adaptive T: per-pixel relative error target (0 = off)
  int maxSpp = 0;                              // --max-spp N: cap of adaptive sampling (0 → 16 × spp)
  double timeBudget = 0.0;                     // --time SECONDS: passes of spp until then (0 = one pass)
  bool quiet = false;
  bool lenient = false;
  std::string statsPath;
  std::vector<std::string> aovs;
  std::string cacheSave, cacheLoad;
  CropFlag crop;                               // --crop X,Y,W,H
  int frames = 0;                              // --frames N with --camera-path (0 = a still)
  std::string cameraPath;                      // --camera-path keyframes.json
  bool cacheReuse = false;                     // --cache-reuse: fill on top of --cache-load
  bool freshFrames = false;                    // --fresh-frames: no cache shared across frames
  int firstFrame = 0, endFrame = 0;            // --frame-range A,B: frames A..B−1 only (0,0 = all)
};

struct DiffArgs {
  std::string a, b, heatmap;
  bool json = false;
};

struct VerifyArgs {
  std::string device = "opencl";
  int order = 0;  // 0 = the standard set
};

RenderArgs parseRenderArgs(const std::vector<std::string>& args);
DiffArgs parseDiffArgs(const std::vector<std::string>& args);
VerifyArgs parseVerifyArgs(const std::vector<std::string>& args);

// Strict number parsing shared by the parsers: the whole string must be a number in [lo, hi].
long long parseInteger(const std::string& flag, const std::string& text, long long lo, long long hi);
double parseReal(const std::string& flag, const std::string& text, double lo, double hi);

const char* usageText();

}  // namespace rc
