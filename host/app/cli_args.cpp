#include "app/cli_args.h"

#include <cerrno>
#include <cstdlib>

#include "app/integrator_registry.h"
#include "core/error.h"
#include "scene/value_parsing.h"

namespace rc {

const char* usageText() {
  return "usage:\n"
         "  rcache SCENE.xml [-o out.exr|png|hdr] [-D name=value]... [--integrator auto|NAME]\n"
         "                   [--spp N] [--device cpu|opencl|opencl:P:D] [-t THREADS] [--seed S] [--quiet]\n"
         "                   [--sampler independent|ldsampler] [--adaptive T] [--max-spp N] [--time SECONDS]\n"
         "                   [--stats out.json] [--aov records,radius,technique,contributors]\n"
         "                   [--cache-save F] [--cache-load F [--cache-reuse]] [--lenient]\n"
         "                   [--crop X,Y,W,H] [--frames N --camera-path keys.json\n"
         "                   [--frame-range A,B] [--fresh-frames]]\n"
         "  rcache cache merge A.rcc B.rcc... -o C.rcc   one cache file of several (deduplicated)\n"
         "  rcache devices                       list OpenCL platforms and devices\n"
         "  rcache verify [--device D] [--order N]   kernels vs scalar reference\n"
         "  rcache diff A B [--json] [--heatmap out.png]   RMSE, relMSE, max abs error\n";
}

long long parseInteger(const std::string& flag, const std::string& text, long long lo, long long hi) {
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE)
    throw Error(flag + ": expected an integer, got '" + text + "'");
  if (v < lo || v > hi)
    throw Error(flag + ": " + text + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

double parseReal(const std::string& flag, const std::string& text, double lo, double hi) {
  double v = 0.0;
  try {
    v = parseNumber(text);  // the scene parser's: whole string, finite
  } catch (const Error&) {
    throw Error(flag + ": expected a number, got '" + text + "'");
  }
  if (v < lo || v > hi)
    throw Error(flag + ": " + text + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

namespace {

// Walks argv with one-token lookahead so "--flag value" errors can name the flag.
class ArgCursor {
 public:
  explicit ArgCursor(const std::vector<std::string>& args) : args_(args) {}
  bool done() const { return i_ >= args_.size(); }
  const std::string& next() { return args_[i_++]; }
  std::string value(const std::string& flag) {
    if (done()) throw Error(flag + ": missing value");
    return next();
  }

 private:
  const std::vector<std::string>& args_;
  size_t i_ = 0;
};

std::vector<std::string> splitCommas(const std::string& text) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!item.empty()) out.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

// -D name=value: a scene or integrator parameter.
void addDefine(const std::string& kv, RenderArgs& r) {
  const size_t eq = kv.find('=');
  if (eq == std::string::npos || eq == 0) throw Error("-D: expected name=value, got '" + kv + "'");
  r.defines[kv.substr(0, eq)] = kv.substr(eq + 1);
}

void addAovs(const std::string& list, RenderArgs& r) {
  for (const std::string& name : splitCommas(list)) {
    if (name != "records" && name != "radius" && name != "technique" && name != "contributors")
      throw Error("--aov: unknown AOV '" + name + "' (known: records, radius, technique, contributors)");
    r.aovs.push_back(name);
  }
}

// --frame-range A,B: frames A..B-1 of the walk.
void setFrameRange(const std::string& flag, const std::string& v, RenderArgs& r) {
  const size_t comma = v.find(',');
  if (comma == std::string::npos) throw Error("--frame-range: expected A,B (frames A..B-1), got '" + v + "'");
  r.firstFrame = static_cast<int>(parseInteger(flag, v.substr(0, comma), 0, 99999));
  r.endFrame = static_cast<int>(parseInteger(flag, v.substr(comma + 1), 1, 100000));
}

// The options that only make sense together, checked once all are read.
void checkOptionCombinations(const RenderArgs& r) {
  if (r.scenePath.empty()) throw Error("no scene file given");
  if ((r.frames > 0) != !r.cameraPath.empty()) throw Error("--frames and --camera-path go together");
  if (r.freshFrames && r.frames == 0) throw Error("--fresh-frames: only with --frames N");
  if (r.endFrame > 0 && (r.frames == 0 || r.firstFrame >= r.endFrame || r.endFrame > r.frames))
    throw Error("--frame-range: A,B needs --frames N and 0 <= A < B <= N");
  if (r.cacheReuse && r.cacheLoad.empty()) throw Error("--cache-reuse: only with --cache-load F");
  if (r.maxSpp > 0 && r.adaptiveThreshold <= 0.0f) throw Error("--max-spp: only with --adaptive T");
  if (r.timeBudget > 0.0 && r.adaptiveThreshold > 0.0f)
    throw Error("--time: not with --adaptive (every pass takes spp samples per pixel)");
  if (r.timeBudget > 0.0 && r.frames > 0) throw Error("--time: not with --frames (a walk renders each frame once)");
  if (r.maxSpp > 0 && r.spp > 0 && r.maxSpp < r.spp)
    throw Error("--max-spp: " + std::to_string(r.maxSpp) + " is below --spp " + std::to_string(r.spp));
}

}  // namespace

RenderArgs parseRenderArgs(const std::vector<std::string>& args) {
  RenderArgs r;
  ArgCursor cur(args);
  while (!cur.done()) {
    const std::string a = cur.next();
    if (a == "-o" || a == "--output") {
      r.outputPath = cur.value(a);
    } else if (a == "-D") {
      addDefine(cur.value(a), r);
    } else if (a == "--integrator") {
      r.integrator = cur.value(a);
      if (r.integrator != "auto" && !findIntegrator(r.integrator))
        throw Error("--integrator: expected auto, " + integratorNames() + ", got '" + r.integrator + "'");
    } else if (a == "--spp") {
      r.spp = static_cast<int>(parseInteger(a, cur.value(a), 1, 1 << 20));
    } else if (a == "--device") {
      r.device = cur.value(a);
    } else if (a == "-t" || a == "--threads") {
      r.threads = static_cast<int>(parseInteger(a, cur.value(a), 1, 1024));
    } else if (a == "--seed") {
      r.seed = static_cast<uint64_t>(parseInteger(a, cur.value(a), 0, (1LL << 62)));
    } else if (a == "--sampler") {
      r.sampler = cur.value(a);
      if (r.sampler != "independent" && r.sampler != "ldsampler")
        throw Error("--sampler: expected independent or ldsampler, got '" + r.sampler + "'");
    } else if (a == "--adaptive") {
      r.adaptiveThreshold = parseReal(a, cur.value(a), 1e-6, 10.0);
    } else if (a == "--time") {
      r.timeBudget = parseReal(a, cur.value(a), 1e-3, 1e7);
    } else if (a == "--max-spp") {
      r.maxSpp = static_cast<int>(parseInteger(a, cur.value(a), 1, 1 << 20));
    } else if (a == "--quiet" || a == "-q") {
      r.quiet = true;
    } else if (a == "--lenient") {
      r.lenient = true;
    } else if (a == "--stats") {
      r.statsPath = cur.value(a);
    } else if (a == "--aov") {
      addAovs(cur.value(a), r);
    } else if (a == "--cache-save") {
      r.cacheSave = cur.value(a);
    } else if (a == "--cache-load") {
      r.cacheLoad = cur.value(a);
    } else if (a == "--crop") {
      r.crop = parseCropFlag(cur.value(a));
    } else if (a == "--frames") {
      r.frames = static_cast<int>(parseInteger(a, cur.value(a), 1, 100000));
    } else if (a == "--camera-path") {
      r.cameraPath = cur.value(a);
    } else if (a == "--cache-reuse") {
      r.cacheReuse = true;
    } else if (a == "--fresh-frames") {
      r.freshFrames = true;
    } else if (a == "--frame-range") {
      setFrameRange(a, cur.value(a), r);
    } else if (!a.empty() && a[0] == '-') {
      throw Error("unknown option '" + a + "'");
    } else if (r.scenePath.empty()) {
      r.scenePath = a;
    } else {
      throw Error("unexpected argument '" + a + "' (scene already given: '" + r.scenePath + "')");
    }
  }
  checkOptionCombinations(r);
  return r;
}

DiffArgs parseDiffArgs(const std::vector<std::string>& args) {
  DiffArgs d;
  ArgCursor cur(args);
  std::vector<std::string> files;
  while (!cur.done()) {
    const std::string a = cur.next();
    if (a == "--json") d.json = true;
    else if (a == "--heatmap") d.heatmap = cur.value(a);
    else if (!a.empty() && a[0] == '-') throw Error("diff: unknown option '" + a + "'");
    else files.push_back(a);
  }
  if (files.size() != 2) throw Error("diff: expected two images (test reference), got " + std::to_string(files.size()));
  d.a = files[0];
  d.b = files[1];
  return d;
}

VerifyArgs parseVerifyArgs(const std::vector<std::string>& args) {
  VerifyArgs v;
  ArgCursor cur(args);
  while (!cur.done()) {
    const std::string a = cur.next();
    if (a == "--device") v.device = cur.value(a);
    else if (a == "--order") v.order = static_cast<int>(parseInteger(a, cur.value(a), 1, 16));
    else throw Error("verify: unknown argument '" + a + "'");
  }
  return v;
}

}  // namespace rc
