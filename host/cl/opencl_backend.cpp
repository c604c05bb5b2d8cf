#include "cl/opencl_backend.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "cl/rotation_tables.h"
#include "core/error.h"
#include "core/math.h"

namespace rc {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// All families share one program per order (few distinct build-option sets: PoCL compiles
// ~1.5 s per program).
const std::vector<std::string> kProgramFiles = {"sh_project.cl", "grad_accumulate.cl", "sh_rotate.cl",
                                                "interpolate.cl", "brdf_dot.cl"};

void checkOrder(const char* fn, int order) {
  if (order < 1 || order > kMaxKernelOrder)
    throw Error(std::string("OpenCL ") + fn + ": order " + std::to_string(order) + " outside 1.." +
                std::to_string(kMaxKernelOrder) + " supported by the kernels");
}

void checkSize(const char* fn, const char* array, size_t actual, long long expected) {
  if (static_cast<long long>(actual) != expected)
    throw Error(std::string("OpenCL ") + fn + ": " + array + " has " + std::to_string(actual) + " values, expected " +
                std::to_string(expected));
}

size_t roundUp(size_t x, size_t m) { return (x + m - 1) / m * m; }

}  // namespace

struct OpenClBackend::OrderState {
  int order = 0;
  cl::Kernel basis, prep, gradPrep, gemm3, gemm9, finish, rotate, interp, brdf;
  cl::Buffer J;
  // Basis matrix cache: the renderer reuses one pattern across batches.
  int basisM = 0, basisN = 0;
  std::vector<float> basisPattern;
  cl::Buffer Y;
  cl::Buffer gradGeometry;  // per-grid constants of grad_accumulate.cl (see rc_grad_prep)
};

OpenClBackend::OpenClBackend(const cl::DeviceInfo& device) : ctx_(cl::Context::forDevice(device)) {
  cl_uint w = 0;
  RC_CL_CHECK(clGetDeviceInfo(device.device, CL_DEVICE_PREFERRED_VECTOR_WIDTH_FLOAT, sizeof(w), &w, nullptr));
  // GEMM tile width: 16 on AVX-512 CPUs, 8 otherwise (GPUs report 1: 8 keeps the padding small).
  vec_ = w >= 16 ? 16 : 8;
  if (const char* v = std::getenv("RC_GEMM_LOCAL1")) gemmLocal_ = std::atoi(v);
  if (const char* v = std::getenv("RC_GEMM_VEC")) vec_ = std::atoi(v) == 16 ? 16 : std::atoi(v) == 4 ? 4 : 8;
  maxBuffer_ = static_cast<size_t>(std::min<unsigned long long>(device.maxAlloc, 256ull << 20));
}

OpenClBackend::~OpenClBackend() = default;

std::string OpenClBackend::deviceName() const {
  return "OpenCL: " + ctx_->info().name + " (" + ctx_->info().platformName + ")";
}

void OpenClBackend::prepare(int order) {
  std::lock_guard<std::mutex> lock(mutex_);
  state(order);
}

OpenClBackend::OrderState& OpenClBackend::state(int order) {
  auto it = states_.find(order);
  if (it != states_.end()) return *it->second;
  auto st = std::make_unique<OrderState>();
  st->order = order;
  const std::string options = "-D RC_ORDER=" + std::to_string(order) + " -D RC_VEC=" + std::to_string(vec_);
  const int cachedBefore = ctx_->programsFromBinaryCache();
  cl_program prog = ctx_->program(kProgramFiles, options);
  ++times_.programs;
  times_.programsFromBinaryCache += ctx_->programsFromBinaryCache() - cachedBefore;
  st->basis = cl::Kernel(prog, "rc_sh_basis");
  st->prep = cl::Kernel(prog, "rc_project_prep");
  st->gradPrep = cl::Kernel(prog, "rc_grad_prep");
  st->gemm3 = cl::Kernel(prog, "rc_project_gemm3");
  st->gemm9 = cl::Kernel(prog, "rc_project_gemm9");
  st->finish = cl::Kernel(prog, "rc_project_finish");
  st->rotate = cl::Kernel(prog, "rc_sh_rotate");
  st->interp = cl::Kernel(prog, "rc_interpolate");
  st->brdf = cl::Kernel(prog, "rc_brdf_dot");
  const std::vector<float>& J = cl::xRotation90Table(order);
  st->J = cl::Buffer(ctx_->context(), CL_MEM_READ_ONLY, J.size() * sizeof(float), J.data());
  return *states_.emplace(order, std::move(st)).first->second;
}

namespace {

// Explicit work-group sizes: left to itself PoCL picks 4096-item groups, and the kernels' private
// arrays (3·n² floats per item) then overflow the worker thread's stack. Global sizes are rounded
// up; every kernel guards its index.
void launch(cl_command_queue q, const cl::Kernel& k, size_t g0, size_t g1 = 1, size_t l0 = 64) {
  if (g0 == 0 || g1 == 0) return;
  const size_t local[2] = {l0, 1};
  const size_t global[2] = {roundUp(g0, l0), g1};
  RC_CL_CHECK(clEnqueueNDRangeKernel(q, k.get(), g1 > 1 ? 2 : 1, nullptr, global, local, 0, nullptr, nullptr));
}

// On CPU devices (host memory is device memory) inputs and outputs wrap the caller's arrays
// with CL_MEM_USE_HOST_PTR: no copies, no fresh allocations per batch. Elsewhere they are copied.
thread_local bool gZeroCopy = false;  // set at the start of each backend call from its device type

template <class T>
void readBack(cl_command_queue q, const cl::Buffer& b, T* dst, size_t count) {
  if (count == 0) return;
  if (gZeroCopy) {  // map/unmap makes the device's writes visible in the wrapped host array
    cl_int err = CL_SUCCESS;
    void* p = clEnqueueMapBuffer(q, b.get(), CL_TRUE, CL_MAP_READ, 0, count * sizeof(T), 0, nullptr, nullptr, &err);
    RC_CL_CHECK_ERR(err, "clEnqueueMapBuffer(queue, buffer, CL_TRUE, CL_MAP_READ, ...)");
    if (p != static_cast<void*>(dst)) std::memcpy(dst, p, count * sizeof(T));
    RC_CL_CHECK(clEnqueueUnmapMemObject(q, b.get(), p, 0, nullptr, nullptr));
    RC_CL_CHECK(clFinish(q));
    return;
  }
  RC_CL_CHECK(clEnqueueReadBuffer(q, b.get(), CL_TRUE, 0, count * sizeof(T), dst, 0, nullptr, nullptr));
}

template <class T>
cl::Buffer input(cl_context c, const T* data, size_t count) {
  if (gZeroCopy && count)
    return cl::Buffer(c, CL_MEM_READ_ONLY | CL_MEM_USE_HOST_PTR, count * sizeof(T), data);
  return cl::Buffer(c, CL_MEM_READ_ONLY, count * sizeof(T), data);
}

template <class T>
cl::Buffer output(cl_context c, T* data, size_t count) {
  if (gZeroCopy && count) return cl::Buffer(c, CL_MEM_WRITE_ONLY | CL_MEM_USE_HOST_PTR, count * sizeof(T), data);
  return cl::Buffer(c, CL_MEM_WRITE_ONLY, count * sizeof(T));
}

}  // namespace

void OpenClBackend::ensureBasis(OrderState& st, const ProjectBatch& b) {
  const size_t S = static_cast<size_t>(b.M) * b.N;
  if (st.basisM == b.M && st.basisN == b.N && st.basisPattern == b.pattern) return;
  const size_t np = roundUp(static_cast<size_t>(st.order) * st.order, vec_);
  if (S * np * sizeof(float) > ctx_->info().maxAlloc)
    throw Error("OpenCL project: basis matrix of " + std::to_string(S) + " samples at order " +
                std::to_string(st.order) + " exceeds the device's maximum allocation");
  cl::Buffer pattern = input(ctx_->context(), b.pattern.data(), b.pattern.size());
  st.Y = cl::Buffer(ctx_->context(), CL_MEM_READ_WRITE, S * np * sizeof(float));
  st.basis.arg(0, static_cast<cl_int>(S));
  st.basis.arg(1, static_cast<cl_int>(b.M));
  st.basis.arg(2, static_cast<cl_int>(b.N));
  st.basis.arg(3, pattern);
  st.basis.arg(4, st.Y);
  launch(ctx_->queue(), st.basis, S);
  RC_CL_CHECK(clFinish(ctx_->queue()));
  // Gradient geometry in double (reference.h): edge factors per elevation boundary, row heights,
  // and per-column (cos, sin) of the cell centre and lower boundary at phi0 = 0.
  const int M = b.M, N = b.N;
  std::vector<float> geo(2 * M + 1 + 4 * N, 0.0f);
  const double arc = 2.0 * std::sin(kPiD / N);
  for (int j = 1; j < M; ++j) {
    const double cj = 1.0 - double(j) / M;
    geo[j] = static_cast<float>(arc * cj * std::sqrt(std::max(0.0, 1.0 - cj * cj)));
  }
  for (int j = 0; j < M; ++j)
    geo[M + 1 + j] = static_cast<float>(std::acos(1.0 - (j + 1.0) / M) - std::acos(1.0 - double(j) / M));
  for (int k = 0; k < N; ++k) {
    const double mid = 2.0 * kPiD * (k + 0.5) / N, lo = 2.0 * kPiD * k / N;
    float* c = geo.data() + 2 * M + 1 + 4 * k;
    c[0] = static_cast<float>(std::cos(mid));
    c[1] = static_cast<float>(std::sin(mid));
    c[2] = static_cast<float>(std::cos(lo));
    c[3] = static_cast<float>(std::sin(lo));
  }
  st.gradGeometry = cl::Buffer(ctx_->context(), CL_MEM_READ_ONLY, geo.size() * sizeof(float), geo.data());
  st.basisM = b.M;
  st.basisN = b.N;
  st.basisPattern = b.pattern;
}

void OpenClBackend::project(const ProjectBatch& b, ProjectResult& out) {
  const auto t0 = Clock::now();
  checkOrder("project", b.order);
  if (b.M < 1 || b.N < 1) throw Error("OpenCL project: cell grid " + std::to_string(b.M) + "x" + std::to_string(b.N) + " must be at least 1x1");
  if (b.records < 0) throw Error("OpenCL project: negative record count");
  if (!(b.minDistance > 0.0f) || !std::isfinite(b.minDistance)) throw Error("OpenCL project: minDistance must be positive and finite");
  const long long S = static_cast<long long>(b.M) * b.N, B = b.records;
  checkSize("project", "pattern", b.pattern.size(), 2 * S);
  checkSize("project", "phi0", b.phi0.size(), B);
  checkSize("project", "radiance", b.radiance.size(), 3 * S * B);
  if (b.gradients) checkSize("project", "distance", b.distance.size(), S * B);
  const int n2 = b.order * b.order;
  const size_t outSize = 3ull * n2 * B;
  out.lambda.assign(outSize, 0.0f);
  out.gradT.assign(b.gradients ? outSize : 0, 0.0f);
  out.gradB.assign(b.gradients ? outSize : 0, 0.0f);
  out.dropped.assign(B, 0);
  if (B > 0) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::lock_guard<std::mutex> qlock(ctx_->queueMutex());
    gZeroCopy = ctx_->info().type == "CPU" && !std::getenv("RC_CL_NO_ZERO_COPY");
    OrderState& st = state(b.order);
    ensureBasis(st, b);
    cl_context c = ctx_->context();
    cl_command_queue q = ctx_->queue();
    const int rows = b.gradients ? 9 : 3;
    const size_t np = roundUp(n2, vec_);
    // The largest per-record buffer is A (S·rows floats); split the batch so it fits.
    const size_t perRecord = static_cast<size_t>(S) * rows * sizeof(float);
    const long long chunk = std::max<long long>(1, std::min<long long>(B, maxBuffer_ / perRecord));
    if (perRecord > ctx_->info().maxAlloc) throw Error("OpenCL project: one record's samples exceed the device's maximum allocation");
    for (long long b0 = 0; b0 < B; b0 += chunk) {
      const long long cnt = std::min(chunk, B - b0);
      cl::Buffer rad = input(c, b.radiance.data() + 3 * S * b0, 3 * S * cnt);
      cl::Buffer phi = input(c, b.phi0.data() + b0, cnt);
      cl::Buffer dist = b.gradients ? input(c, b.distance.data() + S * b0, S * cnt) : cl::Buffer(c, CL_MEM_READ_ONLY, 4);
      cl::Buffer A(c, CL_MEM_READ_WRITE, S * cnt * rows * sizeof(float));
      cl::Buffer C(c, CL_MEM_READ_WRITE, cnt * rows * np * sizeof(float));
      cl::Buffer lam = output(c, out.lambda.data() + 3 * n2 * b0, 3 * n2 * cnt);
      cl::Buffer gT = b.gradients ? output(c, out.gradT.data() + 3 * n2 * b0, 3 * n2 * cnt) : cl::Buffer(c, CL_MEM_WRITE_ONLY, 4);
      cl::Buffer gB = b.gradients ? output(c, out.gradB.data() + 3 * n2 * b0, 3 * n2 * cnt) : cl::Buffer(c, CL_MEM_WRITE_ONLY, 4);
      cl::Buffer dropped(c, CL_MEM_READ_WRITE, cnt * sizeof(cl_int));
      const cl_int zero = 0;
      RC_CL_CHECK(clEnqueueFillBuffer(q, dropped.get(), &zero, sizeof(zero), 0, cnt * sizeof(cl_int), 0, nullptr, nullptr));
      if (b.gradients) {
        std::vector<float> cs(2 * cnt);
        for (long long r = 0; r < cnt; ++r) {
          cs[2 * r] = static_cast<float>(std::cos(double(b.phi0[b0 + r])));
          cs[2 * r + 1] = static_cast<float>(std::sin(double(b.phi0[b0 + r])));
        }
        cl::Buffer phiCS(c, CL_MEM_READ_ONLY, cs.size() * sizeof(float), cs.data());
        cl::Kernel& k = st.gradPrep;
        k.arg(0, static_cast<cl_int>(b.M));
        k.arg(1, static_cast<cl_int>(b.N));
        k.arg(2, static_cast<cl_int>(cnt));
        k.arg(3, b.minDistance);
        k.arg(4, st.gradGeometry);
        k.arg(5, phiCS);
        k.arg(6, rad);
        k.arg(7, dist);
        k.arg(8, A);
        k.arg(9, dropped);
        launch(q, k, S, cnt);
      } else {
        cl::Kernel& k = st.prep;
        k.arg(0, static_cast<cl_int>(S));
        k.arg(1, static_cast<cl_int>(cnt));
        k.arg(2, rad);
        k.arg(3, A);
        k.arg(4, dropped);
        launch(q, k, S, cnt);
      }
      cl::Kernel& g = b.gradients ? st.gemm9 : st.gemm3;
      g.arg(0, static_cast<cl_int>(S));
      g.arg(1, static_cast<cl_int>(cnt));
      g.arg(2, A);
      g.arg(3, st.Y);
      g.arg(4, C);
      launch(q, g, np / vec_, cnt, gemmLocal_ ? 1 : np / vec_);
      cl::Kernel& f = st.finish;
      f.arg(0, static_cast<cl_int>(cnt));
      f.arg(1, static_cast<cl_int>(rows));
      f.arg(2, static_cast<float>(2.0 * kPiD / static_cast<double>(S)));
      f.arg(3, phi);
      f.arg(4, C);
      f.arg(5, lam);
      f.arg(6, gT);
      f.arg(7, gB);
      launch(q, f, rows, cnt, rows);
      readBack(q, lam, out.lambda.data() + 3 * n2 * b0, 3 * n2 * cnt);
      if (b.gradients) {
        readBack(q, gT, out.gradT.data() + 3 * n2 * b0, 3 * n2 * cnt);
        readBack(q, gB, out.gradB.data() + 3 * n2 * b0, 3 * n2 * cnt);
      }
      readBack(q, dropped, out.dropped.data() + b0, cnt);
    }
  }
  times_.project_s += secondsSince(t0);
  times_.projectItems += B;
}

void OpenClBackend::rotate(const RotateBatch& b, std::vector<float>& out) {
  const auto t0 = Clock::now();
  checkOrder("rotate", b.order);
  if (b.count < 0) throw Error("OpenCL rotate: negative count");
  const int n2 = b.order * b.order;
  checkSize("rotate", "rotations", b.rotations.size(), 9ll * b.count);
  checkSize("rotate", "coeffs", b.coeffs.size(), 3ll * n2 * b.count);
  out.assign(3ull * n2 * b.count, 0.0f);
  if (b.count > 0) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::lock_guard<std::mutex> qlock(ctx_->queueMutex());
    gZeroCopy = ctx_->info().type == "CPU" && !std::getenv("RC_CL_NO_ZERO_COPY");
    OrderState& st = state(b.order);
    cl_context c = ctx_->context();
    cl_command_queue q = ctx_->queue();
    const long long per = 3ll * n2 * sizeof(float);
    const long long chunk = std::max<long long>(1, std::min<long long>(b.count, maxBuffer_ / per));
    for (long long b0 = 0; b0 < b.count; b0 += chunk) {
      const long long cnt = std::min<long long>(chunk, b.count - b0);
      cl::Buffer R = input(c, b.rotations.data() + 9 * b0, 9 * cnt);
      cl::Buffer in = input(c, b.coeffs.data() + 3 * n2 * b0, 3 * n2 * cnt);
      cl::Buffer o = output(c, out.data() + 3 * n2 * b0, 3 * n2 * cnt);
      st.rotate.arg(0, static_cast<cl_int>(cnt));
      st.rotate.arg(1, R);
      st.rotate.arg(2, in);
      st.rotate.arg(3, o);
      st.rotate.arg(4, st.J);
      launch(q, st.rotate, cnt);
      readBack(q, o, out.data() + 3 * n2 * b0, 3 * n2 * cnt);
    }
  }
  times_.rotate_s += secondsSince(t0);
  times_.rotateItems += b.count;
}

void OpenClBackend::interpolate(const InterpolateBatch& b, std::vector<float>& out) {
  const auto t0 = Clock::now();
  checkOrder("interpolate", b.order);
  if (b.records < 0 || b.points < 0) throw Error("OpenCL interpolate: negative record or point count");
  const int n2 = b.order * b.order;
  const long long R = b.records, P = b.points;
  checkSize("interpolate", "lambda", b.lambda.size(), 3 * n2 * R);
  if (b.gradients) {
    checkSize("interpolate", "gradT", b.gradT.size(), 3 * n2 * R);
    checkSize("interpolate", "gradB", b.gradB.size(), 3 * n2 * R);
  }
  if (!b.worldFrame) checkSize("interpolate", "recordFrames", b.recordFrames.size(), 9 * R);
  checkSize("interpolate", "pointFrames", b.pointFrames.size(), 9 * P);
  checkSize("interpolate", "offsets", b.offsets.size(), P + 1);
  if (b.offsets[0] != 0 || b.offsets[P] != static_cast<int32_t>(b.entries.size()))
    throw Error("OpenCL interpolate: offsets must start at 0 and end at entries.size() = " + std::to_string(b.entries.size()));
  for (long long p = 0; p < P; ++p)
    if (b.offsets[p + 1] < b.offsets[p]) throw Error("OpenCL interpolate: offsets decrease at point " + std::to_string(p));
  for (size_t e = 0; e < b.entries.size(); ++e)
    if (b.entries[e].record < 0 || b.entries[e].record >= R)
      throw Error("OpenCL interpolate: entry " + std::to_string(e) + " names record " + std::to_string(b.entries[e].record) +
                  " outside [0, " + std::to_string(R) + ")");
  out.assign(3ull * n2 * P, 0.0f);
  if (P > 0) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::lock_guard<std::mutex> qlock(ctx_->queueMutex());
    gZeroCopy = ctx_->info().type == "CPU" && !std::getenv("RC_CL_NO_ZERO_COPY");
    OrderState& st = state(b.order);
    cl_context c = ctx_->context();
    cl_command_queue q = ctx_->queue();
    if (3ull * n2 * R * sizeof(float) > ctx_->info().maxAlloc)
      throw Error("OpenCL interpolate: " + std::to_string(R) + " records exceed the device's maximum allocation");
    cl::Buffer lam = input(c, b.lambda.data(), b.lambda.size());
    cl::Buffer gT = b.gradients ? input(c, b.gradT.data(), b.gradT.size()) : cl::Buffer(c, CL_MEM_READ_ONLY, 4);
    cl::Buffer gB = b.gradients ? input(c, b.gradB.data(), b.gradB.size()) : cl::Buffer(c, CL_MEM_READ_ONLY, 4);
    cl::Buffer rf = b.worldFrame ? cl::Buffer(c, CL_MEM_READ_ONLY, 4) : input(c, b.recordFrames.data(), b.recordFrames.size());
    const long long per = 3ll * n2 * sizeof(float);
    const long long chunk = std::max<long long>(1, std::min<long long>(P, maxBuffer_ / per));
    std::vector<int32_t> offs;
    for (long long p0 = 0; p0 < P; p0 += chunk) {
      const long long cnt = std::min(chunk, P - p0);
      const int32_t e0 = b.offsets[p0], e1 = b.offsets[p0 + cnt];
      offs.assign(b.offsets.begin() + p0, b.offsets.begin() + p0 + cnt + 1);
      for (int32_t& o : offs) o -= e0;
      cl::Buffer pf = input(c, b.pointFrames.data() + 9 * p0, 9 * cnt);
      cl::Buffer ob = input(c, offs.data(), offs.size());
      cl::Buffer eb = e1 > e0 ? input(c, b.entries.data() + e0, e1 - e0) : cl::Buffer(c, CL_MEM_READ_ONLY, sizeof(RcContribution));
      cl::Buffer o = output(c, out.data() + 3 * n2 * p0, 3 * n2 * cnt);
      cl::Kernel& k = st.interp;
      k.arg(0, static_cast<cl_int>(cnt));
      k.arg(1, static_cast<cl_int>(b.worldFrame ? 1 : 0));
      k.arg(2, static_cast<cl_int>(b.gradients ? 1 : 0));
      k.arg(3, lam);
      k.arg(4, gT);
      k.arg(5, gB);
      k.arg(6, rf);
      k.arg(7, pf);
      k.arg(8, ob);
      k.arg(9, eb);
      k.arg(10, st.J);
      k.arg(11, o);
      launch(q, k, cnt);
      readBack(q, o, out.data() + 3 * n2 * p0, 3 * n2 * cnt);
    }
  }
  times_.interpolate_s += secondsSince(t0);
  times_.interpolateItems += P;
}

void OpenClBackend::brdfDot(const BrdfDotBatch& b, std::vector<float>& out) {
  const auto t0 = Clock::now();
  checkOrder("brdfDot", b.order);
  if (b.points < 0) throw Error("OpenCL brdfDot: negative point count");
  const int n2 = b.order * b.order;
  const long long P = b.points;
  checkSize("brdfDot", "lambda", b.lambda.size(), 3 * n2 * P);
  checkSize("brdfDot", "wo", b.wo.size(), 3 * P);
  checkSize("brdfDot", "material", b.material.size(), P);
  for (size_t t = 0; t < b.tables.size(); ++t) {
    const RcBrdfTable& tab = b.tables[t];
    const std::string what = "OpenCL brdfDot: table " + std::to_string(t);
    if (tab.kind != RC_TABLE_ISOTROPIC_1D && tab.kind != RC_TABLE_ANISOTROPIC_2D) throw Error(what + " has unknown kind " + std::to_string(tab.kind));
    if (tab.order < 1 || tab.order > kMaxReferenceOrder) throw Error(what + " has order " + std::to_string(tab.order));
    if (tab.res < (tab.kind == RC_TABLE_ISOTROPIC_1D ? 1 : 2)) throw Error(what + " has resolution " + std::to_string(tab.res) + " below the minimum (1 for 1-D, 2 for 2-D)");
    const long long entries = tab.kind == RC_TABLE_ISOTROPIC_1D ? tab.res : 1ll * tab.res * tab.res;
    if (tab.offset < 0 || tab.offset + entries * 3 * tab.order * tab.order > static_cast<long long>(b.tableData.size()))
      throw Error(what + " reaches past the end of tableData");
  }
  for (long long p = 0; p < P; ++p)
    if (b.material[p] < 0 || b.material[p] >= static_cast<int32_t>(b.tables.size()))
      throw Error("OpenCL brdfDot: point " + std::to_string(p) + " has material " + std::to_string(b.material[p]) +
                  " outside [0, " + std::to_string(b.tables.size()) + ")");
  out.assign(3ull * P, 0.0f);
  if (P > 0) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::lock_guard<std::mutex> qlock(ctx_->queueMutex());
    gZeroCopy = ctx_->info().type == "CPU" && !std::getenv("RC_CL_NO_ZERO_COPY");
    OrderState& st = state(b.order);
    cl_context c = ctx_->context();
    cl_command_queue q = ctx_->queue();
    cl::Buffer tabs = input(c, b.tables.data(), b.tables.size());
    cl::Buffer data = input(c, b.tableData.data(), b.tableData.size());
    const long long per = 3ll * n2 * sizeof(float);
    const long long chunk = std::max<long long>(1, std::min<long long>(P, maxBuffer_ / per));
    for (long long p0 = 0; p0 < P; p0 += chunk) {
      const long long cnt = std::min(chunk, P - p0);
      cl::Buffer lam = input(c, b.lambda.data() + 3 * n2 * p0, 3 * n2 * cnt);
      cl::Buffer wo = input(c, b.wo.data() + 3 * p0, 3 * cnt);
      cl::Buffer mat = input(c, b.material.data() + p0, cnt);
      cl::Buffer o = output(c, out.data() + 3 * p0, 3 * cnt);
      cl::Kernel& k = st.brdf;
      k.arg(0, static_cast<cl_int>(cnt));
      k.arg(1, lam);
      k.arg(2, wo);
      k.arg(3, mat);
      k.arg(4, tabs);
      k.arg(5, static_cast<cl_int>(b.tables.size()));
      k.arg(6, data);
      k.arg(7, o);
      launch(q, k, cnt);
      readBack(q, o, out.data() + 3 * p0, 3 * cnt);
    }
  }
  times_.brdfDot_s += secondsSince(t0);
  times_.brdfDotItems += P;
}

}  // namespace rc
