// rcache-bench-kernels: items/s and GFLOP/s of each kernel family on the OpenCL device, with the
// scalar reference backend (multi-threaded, same machine, same run) in the same row, their ratio
// ("speedup"), and the fraction of the machine's float peak. One JSON line per family and order on
// stdout; at the end, a table of the ratios side by side (family × order) on stderr.
//
//   rcache-bench-kernels [--quick] [--device SPEC] [--orders 5,10] [--cores N] [--peak-gfma-per-core G]
//
// Flops are 2 × the FMAs the algorithm must do (the "useful" work, not what the compiler
// emitted), counted per item below; peak = G GFMA/s per core (default 55: 16-wide AVX-512 FMA ×
// ~2 pipes × ~1.7 GHz sustained — the figure given for this machine) × cores × 2 flops.
// Throughput is host-observed wall time of a backend call, transfers included, as the renderer
// sees it: the fastest of calls alternating between kernel and reference (timeAlternating).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cl/kernel_cases.h"
#include "cl/rotation_tables.h"
#include "cl/sh_backend.h"
#include "core/error.h"

namespace {

using Clock = std::chrono::steady_clock;

// Seconds per call of the kernel and of the reference, taken from alternating calls (kernel,
// reference, kernel, ...) for at least `minSeconds` each and at least 5 rounds, after one warm-up
// call of each (program build, basis matrix, first-touch allocations). Each is the fastest of its
// calls: on a machine shared with other jobs the fastest call is the one least disturbed, and
// alternating exposes both sides to the same neighbours, so their ratio stays fair.
struct CallTimes {
  double kernel, reference;
};
CallTimes timeAlternating(const std::function<void()>& kernel, const std::function<void()>& reference,
                          double minSeconds) {
  kernel();
  reference();
  auto seconds = [](const std::function<void()>& run) {
    const auto t0 = Clock::now();
    run();
    return std::chrono::duration<double>(Clock::now() - t0).count();
  };
  CallTimes best{1e300, 1e300};
  double kernelTotal = 0, referenceTotal = 0;
  for (int round = 0; round < 5 || kernelTotal < minSeconds || referenceTotal < minSeconds; ++round) {
    const double k = seconds(kernel), r = seconds(reference);
    best.kernel = std::min(best.kernel, k);
    best.reference = std::min(best.reference, r);
    kernelTotal += k;
    referenceTotal += r;
  }
  return best;
}

// FMAs of one RGB zxzxz rotation: two products with the x-90° band blocks (their nonzeros only:
// the structural zeros are no work the algorithm must do) + three z-rotations (2 per m ≠ 0
// coefficient), three channels.
double rotateFmas(int order) {
  const std::vector<float>& J = rc::cl::xRotation90Table(order);
  const double x90 = static_cast<double>(std::count_if(J.begin(), J.end(), [](float v) { return v != 0.0f; })) - 1.0;  // band 0 is 1
  return 3.0 * (2.0 * x90 + 3.0 * 2.0 * (order * order - order));
}

struct Row {
  std::string family;
  int order;
  double items, kernelSeconds, refSeconds, fmasPerItem;
};

void print(const Row& r, const std::string& device, double peakGflops) {
  const double ips = r.items / r.kernelSeconds, ref = r.items / r.refSeconds;
  const double gflops = 2.0 * r.fmasPerItem * ips * 1e-9;
  std::printf(
      "{\"family\": \"%s\", \"order\": %d, \"device\": \"%s\", \"items_per_s\": %.6g, \"gflops\": %.4g, "
      "\"ref_items_per_s\": %.6g, \"speedup\": %.3f, \"peak_fraction\": %.4f}\n",
      r.family.c_str(), r.order, device.c_str(), ips, gflops, ref, ips / ref, gflops / peakGflops);
  std::fflush(stdout);
}

// Kernel / reference throughput of every family (rows) at every order (columns).
void printSpeedups(const std::vector<Row>& rows, const std::vector<int>& orders) {
  std::fprintf(stderr, "speedup over the scalar reference (same run)\n%-18s", "family");
  for (int order : orders) std::fprintf(stderr, " %8s", ("n=" + std::to_string(order)).c_str());
  std::fprintf(stderr, "\n");
  std::vector<std::string> families;
  for (const Row& r : rows)
    if (std::find(families.begin(), families.end(), r.family) == families.end()) families.push_back(r.family);
  for (const std::string& f : families) {
    std::fprintf(stderr, "%-18s", f.c_str());
    for (int order : orders)
      for (const Row& r : rows)
        if (r.family == f && r.order == order) std::fprintf(stderr, " %8.2f", r.refSeconds / r.kernelSeconds);
    std::fprintf(stderr, "\n");
  }
}

struct Bench {
  rc::ShBackend& dev;
  rc::ShBackend& ref;
  bool quick;
  double minSeconds;
};

// Projection of 4096-ray records (M = 32, N = 128), with the gradients (9 GEMM rows) or without
// (3 rows: shows what the gradients cost).
Row benchProject(const Bench& bench, int order, bool gradients) {
  const int M = 32, N = 128, S = M * N, B = bench.quick ? 32 : 64;
  rc::ProjectBatch b = rc::cases::makeProjectBatch(order, M, N, B, 1u, gradients, false);
  rc::ProjectResult out;
  Row r{gradients ? "sh_project+grad" : "sh_project", order, double(B), 0, 0, (gradients ? 9.0 : 3.0) * S * order * order};
  rc::ProjectBatch rb = b;
  rb.records = bench.quick ? 4 : 8;  // the reference is slow: time fewer records
  rb.phi0.resize(rb.records);
  rb.radiance.resize(3ull * S * rb.records);
  rb.distance.resize(1ull * S * rb.records);
  rc::ProjectResult refOut;
  const CallTimes t = timeAlternating([&] { bench.dev.project(b, out); }, [&] { bench.ref.project(rb, refOut); },
                                      bench.minSeconds);
  r.kernelSeconds = t.kernel;
  r.refSeconds = t.reference * B / rb.records;
  return r;
}

// One row for a family whose backend call is `call` (batch in, float vector out).
template <class Batch>
Row benchCall(const Bench& bench, const char* family, int order, double items, double fmasPerItem, const Batch& b,
              void (rc::ShBackend::*call)(const Batch&, std::vector<float>&)) {
  std::vector<float> out, refOut;
  const CallTimes t =
      timeAlternating([&] { (bench.dev.*call)(b, out); }, [&] { (bench.ref.*call)(b, refOut); }, bench.minSeconds);
  return Row{family, order, items, t.kernel, t.reference, fmasPerItem};
}

Row benchRotate(const Bench& bench, int order) {
  const int count = 32768;
  const rc::RotateBatch b = rc::cases::makeRotateBatch(order, count, 2u, false);
  return benchCall(bench, "sh_rotate", order, count, rotateFmas(order), b, &rc::ShBackend::rotate);
}

// World-frame mode (the renderer's default): K contributions adjusted + summed, one rotation.
Row benchInterpolate(const Bench& bench, int order) {
  const int points = 8192, records = 512;
  const rc::InterpolateBatch b = rc::cases::makeInterpolateBatch(order, records, points, 3u, true, true);
  const double K = double(b.entries.size()) / points;
  return benchCall(bench, "interpolate", order, points, K * 3.0 * 3.0 * order * order + rotateFmas(order), b,
                   &rc::ShBackend::interpolate);
}

// Three materials, random ω_o. FMAs per coefficient and channel of the folded form (the fewest):
// lerp (1) + the two partial sums P_m, Q_m (2). 32768 points stream their Λ (3n² floats each) from
// memory; "brdf_dot_2k", 2048 points, keeps them in the caches and shows the arithmetic side.
Row benchBrdfDot(const Bench& bench, int order, int points, const char* family) {
  const rc::BrdfDotBatch b = rc::cases::makeBrdfDotBatch(order, points, 4u);
  return benchCall(bench, family, order, points, 3.0 * 3.0 * order * order, b, &rc::ShBackend::brdfDot);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rc;
  bool quick = false;
  std::string deviceSpec = "opencl";
  std::vector<int> orders;
  int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  double gfmaPerCore = 55.0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw Error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--quick") quick = true;
    else if (a == "--device") deviceSpec = next();
    else if (a == "--orders") {
      std::stringstream ss(next());
      std::string t;
      while (std::getline(ss, t, ',')) orders.push_back(std::stoi(t));
    } else if (a == "--cores") cores = std::stoi(next());
    else if (a == "--peak-gfma-per-core") gfmaPerCore = std::stod(next());
    else {
      std::fprintf(stderr, "usage: %s [--quick] [--device SPEC] [--orders 5,10] [--cores N] [--peak-gfma-per-core G]\n", argv[0]);
      return 2;
    }
  }
  if (orders.empty()) orders = quick ? std::vector<int>{10} : std::vector<int>{1, 2, 5, 10, 16};
  try {
    std::unique_ptr<ShBackend> dev = makeShBackend(deviceSpec);
    std::unique_ptr<ShBackend> ref = makeScalarBackend();
    const std::string device = dev->deviceName();
    const double peakGflops = 2.0 * gfmaPerCore * cores;
    const double minT = quick ? 0.25 : 1.0;
    std::vector<Row> rows;
    auto report = [&](const Row& r) {
      print(r, device, peakGflops);
      rows.push_back(r);
    };
    std::fprintf(stderr, "device: %s; reference: %s; peak %.0f GFLOP/s (%d cores x %.0f GFMA/s)\n", device.c_str(),
                 ref->deviceName().c_str(), peakGflops, cores, gfmaPerCore);
    const Bench bench{*dev, *ref, quick, minT};
    for (int order : orders) {
      report(benchProject(bench, order, true));
      report(benchProject(bench, order, false));
      report(benchRotate(bench, order));
      report(benchInterpolate(bench, order));
      report(benchBrdfDot(bench, order, 32768, "brdf_dot"));
      report(benchBrdfDot(bench, order, 2048, "brdf_dot_2k"));
    }
    printSpeedups(rows, orders);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rcache-bench-kernels: %s\n", e.what());
    return 1;
  }
  return 0;
}
