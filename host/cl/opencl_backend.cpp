#include "cl/opencl_backend.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <vector>

#include "cl/device_tuning.h"
#include "cl/rotation_tables.h"
#include "core/error.h"
#include "core/math.h"
#include "core/timing.h"

namespace rc {

namespace {


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

// Work-group size of the kernels that hold RC_VEC items per work-item (3·n² vectors each).
constexpr size_t kPacksPerGroup = 4;

}  // namespace

struct OpenClBackend::OrderState {
  int order = 0;
  cl::Kernel basis, prep, gradPrep, gemm3, gemm9, finish, rotate, interpWorld, interpRecord, brdf;
  cl::Buffer x90Rows, x90Entries;  // sparse x-90° band blocks, J then Jᵀ (cl/rotation_tables.h)
  // Basis matrix cache: the renderer reuses one pattern across batches.
  int basisM = 0, basisN = 0;
  std::vector<float> basisPattern;
  cl::Buffer Y;
  cl::Buffer gradGeometry;  // per-grid constants of grad_accumulate.cl (see rc_grad_prep)
};

OpenClBackend::OpenClBackend(const cl::DeviceInfo& device)
    : ctx_(cl::Context::forDevice(device)), tuning_(cl::tuningFor(device)) {
  maxBuffer_ = static_cast<size_t>(std::min<unsigned long long>(device.maxAlloc, 256ull << 20));
}

OpenClBackend::~OpenClBackend() = default;

std::string OpenClBackend::deviceName() const {
  return "OpenCL: " + ctx_->info().name + " (" + ctx_->info().platformName + ")";
}

int OpenClBackend::kernelThreads() const { return ctx_->info().type == "CPU" ? ctx_->info().computeUnits : 0; }

void OpenClBackend::prepare(int order) {
  std::lock_guard<std::mutex> lock(mutex_);
  state(order);
}

OpenClBackend::OrderState& OpenClBackend::state(int order) {
  auto it = states_.find(order);
  if (it != states_.end()) return *it->second;
  auto st = std::make_unique<OrderState>();
  st->order = order;
  const std::string options =
      "-D RC_ORDER=" + std::to_string(order) + " -D RC_VEC=" + std::to_string(tuning_.vectorWidth);
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
  st->interpWorld = cl::Kernel(prog, "rc_interpolate_world");
  st->interpRecord = cl::Kernel(prog, "rc_interpolate_record");
  st->brdf = cl::Kernel(prog, "rc_brdf_dot");
  const cl::SparseRotation90& x90 = cl::xRotation90Sparse(order);
  st->x90Rows = cl::Buffer(ctx_->context(), CL_MEM_READ_ONLY, x90.rowStart.size() * sizeof(rc_int), x90.rowStart.data());
  st->x90Entries =
      cl::Buffer(ctx_->context(), CL_MEM_READ_ONLY, x90.entries.size() * sizeof(RcSparseEntry), x90.entries.data());
  return *states_.emplace(order, std::move(st)).first->second;
}

// What one backend call holds while it enqueues: the backend's lock (order states, basis cache)
// and the queue's, the order's kernels, and the buffer helpers. On devices whose memory is host
// memory (tuning zeroCopy) inputs and outputs wrap the caller's arrays with CL_MEM_USE_HOST_PTR: no
// copies, no fresh allocations per batch. Elsewhere they are copied.
class OpenClBackend::Call {
 public:
  Call(OpenClBackend& backend, int order)
      : lock_(backend.mutex_),
        queueLock_(backend.ctx_->queueMutex()),
        st(backend.state(order)),
        context(backend.ctx_->context()),
        queue(backend.ctx_->queue()),
        zeroCopy_(backend.tuning_.zeroCopy) {}

  template <class T>
  cl::Buffer input(const T* data, size_t count) const {
    if (zeroCopy_ && count)
      return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_USE_HOST_PTR, count * sizeof(T), data);
    return cl::Buffer(context, CL_MEM_READ_ONLY, count * sizeof(T), data);
  }
  template <class T>
  cl::Buffer output(T* data, size_t count) const {
    if (zeroCopy_ && count) return cl::Buffer(context, CL_MEM_WRITE_ONLY | CL_MEM_USE_HOST_PTR, count * sizeof(T), data);
    return cl::Buffer(context, CL_MEM_WRITE_ONLY, count * sizeof(T));
  }
  // Binds an argument the kernel does not read in this mode (OpenCL needs a valid buffer).
  cl::Buffer unused() const { return cl::Buffer(context, CL_MEM_READ_WRITE, 4); }
  cl::Buffer scratch(size_t bytes) const { return cl::Buffer(context, CL_MEM_READ_WRITE, bytes); }

  // One output buffer to bring back into the host array `dst` (count items of T).
  struct Read {
    const cl::Buffer* buffer;
    void* dst;
    size_t bytes;
    template <class T>
    Read(const cl::Buffer& b, T* d, size_t count) : buffer(&b), dst(d), bytes(count * sizeof(T)) {}
  };
  // Brings several outputs back with one wait for the device, not one per buffer: each wait is a
  // sleep of the calling thread and a wake-up of the device's threads. Zero-copy outputs wrap the
  // host arrays themselves (CL_MEM_USE_HOST_PTR); a read into the wrapped array is the standard's
  // way to make the device's writes visible there (allowed once the commands using the buffer are
  // done, which the in-order queue guarantees) and needs one wait, where map and unmap need two.
  void readBack(std::initializer_list<Read> reads) const {
    for (const Read& r : reads)
      if (r.bytes)
        RC_CL_CHECK(clEnqueueReadBuffer(queue, r.buffer->get(), CL_FALSE, 0, r.bytes, r.dst, 0, nullptr, nullptr));
    RC_CL_CHECK(clFinish(queue));
  }

  // Explicit work-group sizes: left to itself PoCL picks 4096-item groups, and the kernels'
  // private arrays (3·n² floats per item) then overflow the worker thread's stack. Global sizes
  // are rounded up; every kernel guards its index.
  void launch(const cl::Kernel& k, size_t g0, size_t g1 = 1, size_t l0 = 64) const {
    if (g0 == 0 || g1 == 0) return;
    const size_t local[2] = {l0, 1};
    const size_t global[2] = {roundUp(g0, l0), g1};
    RC_CL_CHECK(clEnqueueNDRangeKernel(queue, k.get(), g1 > 1 ? 2 : 1, nullptr, global, local, 0, nullptr, nullptr));
  }

 private:
  std::lock_guard<std::mutex> lock_, queueLock_;

 public:
  OrderState& st;
  const cl_context context;
  const cl_command_queue queue;

 private:
  const bool zeroCopy_;
};

namespace {

// Items per launch so that the largest buffer (bytesPerItem each) stays within `maxBuffer`.
long long chunkItems(long long items, size_t bytesPerItem, size_t maxBuffer) {
  return std::max<long long>(1, std::min<long long>(items, static_cast<long long>(maxBuffer / bytesPerItem)));
}

// Gradient geometry in double (reference.h): edge factors per elevation boundary, row heights,
// and per-column (cos, sin) of the cell centre and lower boundary at phi0 = 0.
std::vector<float> gradientGeometry(int M, int N) {
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
  return geo;
}

void validateProject(const ProjectBatch& b) {
  checkOrder("project", b.order);
  if (b.M < 1 || b.N < 1)
    throw Error("OpenCL project: cell grid " + std::to_string(b.M) + "x" + std::to_string(b.N) + " must be at least 1x1");
  if (b.records < 0) throw Error("OpenCL project: negative record count");
  if (!(b.minDistance > 0.0f) || !std::isfinite(b.minDistance))
    throw Error("OpenCL project: minDistance must be positive and finite");
  const long long S = static_cast<long long>(b.M) * b.N, B = b.records;
  checkSize("project", "pattern", b.pattern.size(), 2 * S);
  checkSize("project", "phi0", b.phi0.size(), B);
  checkSize("project", "radiance", b.radiance.size(), 3 * S * B);
  if (b.gradients) checkSize("project", "distance", b.distance.size(), S * B);
}

void validateInterpolate(const InterpolateBatch& b) {
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
    throw Error("OpenCL interpolate: offsets must start at 0 and end at entries.size() = " +
                std::to_string(b.entries.size()));
  for (long long p = 0; p < P; ++p)
    if (b.offsets[p + 1] < b.offsets[p]) throw Error("OpenCL interpolate: offsets decrease at point " + std::to_string(p));
  for (size_t e = 0; e < b.entries.size(); ++e)
    if (b.entries[e].record < 0 || b.entries[e].record >= R)
      throw Error("OpenCL interpolate: entry " + std::to_string(e) + " names record " +
                  std::to_string(b.entries[e].record) + " outside [0, " + std::to_string(R) + ")");
}

void validateBrdfDot(const BrdfDotBatch& b) {
  checkOrder("brdfDot", b.order);
  if (b.points < 0) throw Error("OpenCL brdfDot: negative point count");
  const long long P = b.points;
  checkSize("brdfDot", "lambda", b.lambda.size(), 3ll * b.order * b.order * P);
  checkSize("brdfDot", "wo", b.wo.size(), 3 * P);
  checkSize("brdfDot", "material", b.material.size(), P);
  for (size_t t = 0; t < b.tables.size(); ++t) {
    const RcBrdfTable& tab = b.tables[t];
    const std::string what = "OpenCL brdfDot: table " + std::to_string(t);
    if (tab.kind != RC_TABLE_ISOTROPIC_1D && tab.kind != RC_TABLE_ANISOTROPIC_2D)
      throw Error(what + " has unknown kind " + std::to_string(tab.kind));
    if (tab.order < 1 || tab.order > kMaxReferenceOrder) throw Error(what + " has order " + std::to_string(tab.order));
    if (tab.res < (tab.kind == RC_TABLE_ISOTROPIC_1D ? 1 : 2))
      throw Error(what + " has resolution " + std::to_string(tab.res) + " below the minimum (1 for 1-D, 2 for 2-D)");
    const long long entries = tab.kind == RC_TABLE_ISOTROPIC_1D ? tab.res : 1ll * tab.res * tab.res;
    if (tab.offset < 0 || tab.offset + entries * 3 * tab.order * tab.order > static_cast<long long>(b.tableData.size()))
      throw Error(what + " reaches past the end of tableData");
  }
  for (long long p = 0; p < P; ++p)
    if (b.material[p] < 0 || b.material[p] >= static_cast<int32_t>(b.tables.size()))
      throw Error("OpenCL brdfDot: point " + std::to_string(p) + " has material " + std::to_string(b.material[p]) +
                  " outside [0, " + std::to_string(b.tables.size()) + ")");
}

}  // namespace

void OpenClBackend::ensureBasis(Call& call, const ProjectBatch& b) {
  OrderState& st = call.st;
  const size_t S = static_cast<size_t>(b.M) * b.N;
  if (st.basisM == b.M && st.basisN == b.N && st.basisPattern == b.pattern) return;
  const size_t np = roundUp(static_cast<size_t>(st.order) * st.order, tuning_.vectorWidth);
  if (S * np * sizeof(float) > ctx_->info().maxAlloc)
    throw Error("OpenCL project: basis matrix of " + std::to_string(S) + " samples at order " +
                std::to_string(st.order) + " exceeds the device's maximum allocation");
  cl::Buffer pattern = call.input(b.pattern.data(), b.pattern.size());
  st.Y = call.scratch(S * np * sizeof(float));
  st.basis.args(static_cast<cl_int>(S), static_cast<cl_int>(b.M), static_cast<cl_int>(b.N), pattern, st.Y);
  // No wait: the queue is in order, so the projection's kernels run after this one, and the
  // chunk's read-back waits for all of them.
  call.launch(st.basis, S);
  const std::vector<float> geo = gradientGeometry(b.M, b.N);
  st.gradGeometry = cl::Buffer(call.context, CL_MEM_READ_ONLY, geo.size() * sizeof(float), geo.data());
  st.basisM = b.M;
  st.basisN = b.N;
  st.basisPattern = b.pattern;
}

// Records [b0, b0 + cnt) of one projection: per-sample rows (prep), GEMM with the basis, finish.
void OpenClBackend::projectChunk(Call& call, const ProjectBatch& b, long long b0, long long cnt, ProjectResult& out) {
  OrderState& st = call.st;
  const long long S = static_cast<long long>(b.M) * b.N;
  const int n2 = b.order * b.order, rows = b.gradients ? 9 : 3;
  const size_t np = roundUp(n2, tuning_.vectorWidth), outCount = 3 * n2 * cnt, outFirst = 3 * n2 * b0;
  cl::Buffer rad = call.input(b.radiance.data() + 3 * S * b0, 3 * S * cnt);
  cl::Buffer phi = call.input(b.phi0.data() + b0, cnt);
  cl::Buffer A = call.scratch(S * cnt * rows * sizeof(float));
  cl::Buffer C = call.scratch(cnt * rows * np * sizeof(float));
  cl::Buffer lam = call.output(out.lambda.data() + outFirst, outCount);
  cl::Buffer gT = b.gradients ? call.output(out.gradT.data() + outFirst, outCount) : call.unused();
  cl::Buffer gB = b.gradients ? call.output(out.gradB.data() + outFirst, outCount) : call.unused();
  cl::Buffer dropped = call.scratch(cnt * sizeof(cl_int));
  const cl_int zero = 0;
  RC_CL_CHECK(clEnqueueFillBuffer(call.queue, dropped.get(), &zero, sizeof(zero), 0, cnt * sizeof(cl_int), 0, nullptr,
                                  nullptr));
  if (b.gradients) {
    std::vector<float> cs(2 * cnt);  // (cos, sin) of each record's phi0, see rc_grad_prep
    for (long long r = 0; r < cnt; ++r) {
      cs[2 * r] = static_cast<float>(std::cos(double(b.phi0[b0 + r])));
      cs[2 * r + 1] = static_cast<float>(std::sin(double(b.phi0[b0 + r])));
    }
    cl::Buffer phiCS(call.context, CL_MEM_READ_ONLY, cs.size() * sizeof(float), cs.data());
    cl::Buffer dist = call.input(b.distance.data() + S * b0, S * cnt);
    st.gradPrep.args(static_cast<cl_int>(b.M), static_cast<cl_int>(b.N), static_cast<cl_int>(cnt), b.minDistance,
                     st.gradGeometry, phiCS, rad, dist, A, dropped);
    call.launch(st.gradPrep, S, cnt);
  } else {
    st.prep.args(static_cast<cl_int>(S), static_cast<cl_int>(cnt), rad, A, dropped);
    call.launch(st.prep, S, cnt);
  }
  cl::Kernel& gemm = b.gradients ? st.gemm9 : st.gemm3;
  gemm.args(static_cast<cl_int>(S), static_cast<cl_int>(cnt), A, st.Y, C);
  call.launch(gemm, np / tuning_.vectorWidth, cnt, np / tuning_.vectorWidth);
  st.finish.args(static_cast<cl_int>(cnt), static_cast<cl_int>(rows), static_cast<float>(2.0 * kPiD / double(S)), phi, C,
                 lam, gT, gB);
  call.launch(st.finish, rows, cnt, rows);
  const size_t gradCount = b.gradients ? outCount : 0;  // no gradients: empty arrays, nothing read
  call.readBack({{lam, out.lambda.data() + outFirst, outCount},
                 {gT, b.gradients ? out.gradT.data() + outFirst : nullptr, gradCount},
                 {gB, b.gradients ? out.gradB.data() + outFirst : nullptr, gradCount},
                 {dropped, out.dropped.data() + b0, static_cast<size_t>(cnt)}});
}

void OpenClBackend::project(const ProjectBatch& b, ProjectResult& out) {
  const auto t0 = SteadyClock::now();
  validateProject(b);
  const long long S = static_cast<long long>(b.M) * b.N, B = b.records;
  const size_t outSize = 3ull * b.order * b.order * B;
  out.lambda.assign(outSize, 0.0f);
  out.gradT.assign(b.gradients ? outSize : 0, 0.0f);
  out.gradB.assign(b.gradients ? outSize : 0, 0.0f);
  out.dropped.assign(B, 0);
  if (B > 0) {
    // The largest per-record buffer is A (S·rows floats); split the batch so it fits.
    const size_t perRecord = static_cast<size_t>(S) * (b.gradients ? 9 : 3) * sizeof(float);
    if (perRecord > ctx_->info().maxAlloc)
      throw Error("OpenCL project: one record's samples exceed the device's maximum allocation");
    Call call(*this, b.order);
    ensureBasis(call, b);
    const long long chunk = chunkItems(B, perRecord, maxBuffer_);
    for (long long b0 = 0; b0 < B; b0 += chunk) projectChunk(call, b, b0, std::min(chunk, B - b0), out);
  }
  times_.project_s += secondsSince(t0);
}

void OpenClBackend::rotate(const RotateBatch& b, std::vector<float>& out) {
  const auto t0 = SteadyClock::now();
  checkOrder("rotate", b.order);
  if (b.count < 0) throw Error("OpenCL rotate: negative count");
  const int n2 = b.order * b.order;
  checkSize("rotate", "rotations", b.rotations.size(), 9ll * b.count);
  checkSize("rotate", "coeffs", b.coeffs.size(), 3ll * n2 * b.count);
  out.assign(3ull * n2 * b.count, 0.0f);
  if (b.count > 0) {
    Call call(*this, b.order);
    OrderState& st = call.st;
    const long long chunk = chunkItems(b.count, 3ull * n2 * sizeof(float), maxBuffer_);
    for (long long b0 = 0; b0 < b.count; b0 += chunk) {
      const long long cnt = std::min<long long>(chunk, b.count - b0);
      cl::Buffer R = call.input(b.rotations.data() + 9 * b0, 9 * cnt);
      cl::Buffer in = call.input(b.coeffs.data() + 3 * n2 * b0, 3 * n2 * cnt);
      cl::Buffer o = call.output(out.data() + 3 * n2 * b0, 3 * n2 * cnt);
      st.rotate.args(static_cast<cl_int>(cnt), R, in, o, st.x90Rows, st.x90Entries);
      call.launch(st.rotate, packs(cnt), 1, kPacksPerGroup);
      call.readBack({{o, out.data() + 3 * n2 * b0, static_cast<size_t>(3 * n2 * cnt)}});
    }
  }
  times_.rotate_s += secondsSince(t0);
}

void OpenClBackend::interpolate(const InterpolateBatch& b, std::vector<float>& out) {
  const auto t0 = SteadyClock::now();
  validateInterpolate(b);
  const int n2 = b.order * b.order;
  const long long R = b.records, P = b.points;
  out.assign(3ull * n2 * P, 0.0f);
  if (P > 0) {
    if (3ull * n2 * R * sizeof(float) > ctx_->info().maxAlloc)
      throw Error("OpenCL interpolate: " + std::to_string(R) + " records exceed the device's maximum allocation");
    Call call(*this, b.order);
    OrderState& st = call.st;
    cl::Buffer lam = call.input(b.lambda.data(), b.lambda.size());
    cl::Buffer gT = b.gradients ? call.input(b.gradT.data(), b.gradT.size()) : call.unused();
    cl::Buffer gB = b.gradients ? call.input(b.gradB.data(), b.gradB.size()) : call.unused();
    cl::Buffer rf = b.worldFrame ? call.unused() : call.input(b.recordFrames.data(), b.recordFrames.size());
    const long long chunk = chunkItems(P, 3ull * n2 * sizeof(float), maxBuffer_);
    std::vector<int32_t> offs;
    for (long long p0 = 0; p0 < P; p0 += chunk) {
      const long long cnt = std::min(chunk, P - p0);
      const int32_t e0 = b.offsets[p0], e1 = b.offsets[p0 + cnt];
      offs.assign(b.offsets.begin() + p0, b.offsets.begin() + p0 + cnt + 1);
      for (int32_t& o : offs) o -= e0;
      cl::Buffer pf = call.input(b.pointFrames.data() + 9 * p0, 9 * cnt);
      cl::Buffer ob = call.input(offs.data(), offs.size());
      cl::Buffer eb = e1 > e0 ? call.input(b.entries.data() + e0, e1 - e0) : call.unused();
      cl::Buffer o = call.output(out.data() + 3 * n2 * p0, 3 * n2 * cnt);
      const cl_int points = static_cast<cl_int>(cnt), gradients = b.gradients ? 1 : 0;
      if (b.worldFrame) {
        st.interpWorld.args(points, gradients, lam, gT, gB, pf, ob, eb, st.x90Rows, st.x90Entries, o);
        call.launch(st.interpWorld, packs(cnt), 1, kPacksPerGroup);
      } else {
        st.interpRecord.args(points, gradients, lam, gT, gB, rf, pf, ob, eb, st.x90Rows, st.x90Entries, o);
        call.launch(st.interpRecord, cnt);
      }
      call.readBack({{o, out.data() + 3 * n2 * p0, static_cast<size_t>(3 * n2 * cnt)}});
    }
  }
  times_.interpolate_s += secondsSince(t0);
}

void OpenClBackend::brdfDot(const BrdfDotBatch& b, std::vector<float>& out) {
  const auto t0 = SteadyClock::now();
  validateBrdfDot(b);
  const int n2 = b.order * b.order;
  const long long P = b.points;
  out.assign(3ull * P, 0.0f);
  if (P > 0) {
    Call call(*this, b.order);
    OrderState& st = call.st;
    cl::Buffer tabs = call.input(b.tables.data(), b.tables.size());
    cl::Buffer data = call.input(b.tableData.data(), b.tableData.size());
    const long long chunk = chunkItems(P, 3ull * n2 * sizeof(float), maxBuffer_);
    for (long long p0 = 0; p0 < P; p0 += chunk) {
      const long long cnt = std::min(chunk, P - p0);
      cl::Buffer lam = call.input(b.lambda.data() + 3 * n2 * p0, 3 * n2 * cnt);
      cl::Buffer wo = call.input(b.wo.data() + 3 * p0, 3 * cnt);
      cl::Buffer mat = call.input(b.material.data() + p0, cnt);
      cl::Buffer o = call.output(out.data() + 3 * p0, 3 * cnt);
      st.brdf.args(static_cast<cl_int>(cnt), lam, wo, mat, tabs, static_cast<cl_int>(b.tables.size()), data, o);
      call.launch(st.brdf, cnt);
      call.readBack({{o, out.data() + 3 * p0, static_cast<size_t>(3 * cnt)}});
    }
  }
  times_.brdfDot_s += secondsSince(t0);
}

}  // namespace rc
