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
// sees it.
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

// Calls `run` repeatedly for at least `minSeconds` (after one warm-up call) and returns the
// best per-call time of the timed calls' average over groups (robust to a noisy neighbour).
double timePerCall(const std::function<void()>& run, double minSeconds) {
  run();  // warm-up: program build, basis matrix, first-touch allocations
  int calls = 0;
  const auto t0 = Clock::now();
  double elapsed = 0;
  do {
    run();
    ++calls;
    elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
  } while (elapsed < minSeconds);
  return elapsed / calls;
}

// FMAs of one RGB zxzxz rotation: two products with the x-90° band blocks (their nonzeros only:
// the structural zeros are no work the algorithm must do) + three z-rotations (2 per m ≠ 0
// coefficient), three channels.
double rotateFmas(int order) {
  const double x90 = static_cast<double>(rc::cl::xRotation90Sparse(order).entries.size()) / 2.0 - 1.0;  // J and Jᵀ; band 0 is 1
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
    for (int order : orders) {
      const int n2 = order * order;
      {  // projection + gradients of 4096-ray records (M = 32, N = 128)
        const int M = 32, N = 128, S = M * N, B = quick ? 32 : 64;
        ProjectBatch b = cases::makeProjectBatch(order, M, N, B, 1u, true, false);
        ProjectResult out;
        Row r{"sh_project+grad", order, double(B), 0, 0, 9.0 * S * n2};  // GEMM: 9 rows × S × n²
        r.kernelSeconds = timePerCall([&] { dev->project(b, out); }, minT);
        ProjectBatch rb = b;
        rb.records = quick ? 4 : 8;  // the reference is slow: time fewer records
        rb.phi0.resize(rb.records);
        rb.radiance.resize(3ull * S * rb.records);
        rb.distance.resize(1ull * S * rb.records);
        r.refSeconds = timePerCall([&] { ref->project(rb, out); }, minT) * B / rb.records;
        report(r);
      }
      {  // projection alone (3 GEMM rows instead of 9): shows what the gradients cost
        const int M = 32, N = 128, S = M * N, B = quick ? 32 : 64;
        ProjectBatch b = cases::makeProjectBatch(order, M, N, B, 1u, false, false);
        ProjectResult out;
        Row r{"sh_project", order, double(B), 0, 0, 3.0 * S * n2};
        r.kernelSeconds = timePerCall([&] { dev->project(b, out); }, minT);
        ProjectBatch rb = b;
        rb.records = quick ? 4 : 8;
        rb.phi0.resize(rb.records);
        rb.radiance.resize(3ull * S * rb.records);
        rb.distance.resize(1ull * S * rb.records);
        r.refSeconds = timePerCall([&] { ref->project(rb, out); }, minT) * B / rb.records;
        report(r);
      }
      {
        const int count = 32768;
        RotateBatch b = cases::makeRotateBatch(order, count, 2u, false);
        std::vector<float> out;
        Row r{"sh_rotate", order, double(count), 0, 0, rotateFmas(order)};
        r.kernelSeconds = timePerCall([&] { dev->rotate(b, out); }, minT);
        r.refSeconds = timePerCall([&] { ref->rotate(b, out); }, minT);
        report(r);
      }
      {  // world-frame mode (the renderer's default): K contributions adjusted + summed, one rotation
        const int points = 8192, records = 512;
        InterpolateBatch b = cases::makeInterpolateBatch(order, records, points, 3u, true, true);
        const double K = double(b.entries.size()) / points;
        std::vector<float> out;
        Row r{"interpolate", order, double(points), 0, 0, K * 3.0 * 3.0 * n2 + rotateFmas(order)};
        r.kernelSeconds = timePerCall([&] { dev->interpolate(b, out); }, minT);
        r.refSeconds = timePerCall([&] { ref->interpolate(b, out); }, minT);
        report(r);
      }
      {  // three materials, random ω_o; per coefficient and channel: lerp (1 FMA) + P/Q (2 FMA)
        const int points = 32768;
        BrdfDotBatch b = cases::makeBrdfDotBatch(order, points, 4u);
        std::vector<float> out;
        Row r{"brdf_dot", order, double(points), 0, 0, 3.0 * 3.0 * n2};
        r.kernelSeconds = timePerCall([&] { dev->brdfDot(b, out); }, minT);
        r.refSeconds = timePerCall([&] { ref->brdfDot(b, out); }, minT);
        report(r);
      }
    }
    printSpeedups(rows, orders);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rcache-bench-kernels: %s\n", e.what());
    return 1;
  }
  return 0;
}
