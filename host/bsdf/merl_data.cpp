#include "bsdf/merl_data.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/user_cache.h"

namespace rc {

namespace {

constexpr double kHalfPi = 0.5 * kPiD;

double clampUnit(double x) { return std::fmax(-1.0, std::fmin(1.0, x)); }

// Continuous index x on an axis of n nodes held at the last node: the two nodes and the weight of
// the upper one.
void clampedCell(double x, int n, int* i0, int* i1, double* t) {
  x = std::fmax(0.0, x);
  const int i = static_cast<int>(x);
  if (i >= n - 1) {
    *i0 = *i1 = n - 1;
    *t = 0.0;
    return;
  }
  *i0 = i;
  *i1 = i + 1;
  *t = x - i;
}

}  // namespace

HalfDiffAngles halfDiffAngles(const Vec3& wi, const Vec3& wo) {
  double hx = double(wi.x) + wo.x, hy = double(wi.y) + wo.y, hz = double(wi.z) + wo.z;
  const double len = std::sqrt(hx * hx + hy * hy + hz * hz);
  HalfDiffAngles a;
  if (!(len > 0.0)) return a;  // opposite directions: no half vector (never both above the surface)
  hx /= len, hy /= len, hz /= len;
  a.thetaHalf = std::acos(clampUnit(hz));
  const double phiHalf = std::atan2(hy, hx);
  // ω_i in the half vector's frame: rotate by −φ_h about z, then by −θ_h about y.
  const double cp = std::cos(phiHalf), sp = std::sin(phiHalf);
  const double x1 = wi.x * cp + wi.y * sp, y1 = -wi.x * sp + wi.y * cp, z1 = wi.z;
  const double ct = std::cos(a.thetaHalf), st = std::sin(a.thetaHalf);
  const double dx = x1 * ct - z1 * st, dy = y1, dz = x1 * st + z1 * ct;
  const double dlen = std::sqrt(dx * dx + dy * dy + dz * dz);
  a.thetaDiff = std::acos(clampUnit(dz / dlen));
  double phi = std::atan2(dy, dx);
  if (phi < 0.0) phi += kPiD;  // reciprocity: φ_d and φ_d + π are the same configuration
  if (phi >= kPiD) phi -= kPiD;
  a.phiDiff = phi;
  return a;
}

void directionsFromHalfDiff(double thetaHalf, double thetaDiff, double phiDiff, Vec3* wi, Vec3* wo) {
  const double sd = std::sin(thetaDiff), dx = sd * std::cos(phiDiff), dy = sd * std::sin(phiDiff),
               dz = std::cos(thetaDiff);
  const double ct = std::cos(thetaHalf), st = std::sin(thetaHalf);
  const double ix = dx * ct + dz * st, iy = dy, iz = -dx * st + dz * ct;
  const double hx = st, hz = ct, dot = ix * hx + iz * hz;
  *wi = Vec3(float(ix), float(iy), float(iz));
  *wo = Vec3(float(2.0 * dot * hx - ix), float(-iy), float(2.0 * dot * hz - iz));
}

double MerlData::nodeThetaHalf(int i) const {
  const double u = double(i) / thetaHalfRes;
  return u * u * kHalfPi;
}
double MerlData::nodeThetaDiff(int j) const { return double(j) / thetaDiffRes * kHalfPi; }
double MerlData::nodePhiDiff(int k) const { return double(k) / phiDiffRes * kPiD; }

Color MerlData::lookup(const HalfDiffAngles& a) const {
  int h0, h1, d0, d1;
  double th, td;
  clampedCell(std::sqrt(std::fmax(0.0, a.thetaHalf) / kHalfPi) * thetaHalfRes, thetaHalfRes, &h0, &h1, &th);
  clampedCell(a.thetaDiff / kHalfPi * thetaDiffRes, thetaDiffRes, &d0, &d1, &td);
  const double xp = std::fmax(0.0, a.phiDiff) / kPiD * phiDiffRes;
  const int p0 = static_cast<int>(xp) % phiDiffRes, p1 = (p0 + 1) % phiDiffRes;
  const double tp = xp - std::floor(xp);
  Color out(0.0f);
  for (int c = 0; c < 3; ++c) {
    auto v = [&](int i, int j, int k) { return double(values[index(c, i, j, k)]); };
    auto alongPhi = [&](int i, int j) { return v(i, j, p0) * (1.0 - tp) + v(i, j, p1) * tp; };
    auto alongDiff = [&](int i) { return alongPhi(i, d0) * (1.0 - td) + alongPhi(i, d1) * td; };
    out[c] = static_cast<float>(alongDiff(h0) * (1.0 - th) + alongDiff(h1) * th);
  }
  return out;
}

MerlData readMerlFile(const std::string& path, bool clampNegative) {
  auto fail = [&](const std::string& why) -> void { throw Error("MERL file " + path + ": " + why); };
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail("is a directory");
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    fail("not a regular file");  // a FIFO would block, /dev/zero report an endless length
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) fail(std::string("cannot open (") + std::strerror(errno) + ")");
  const std::streamoff size = f.tellg();
  if (size < 0) fail("cannot determine the file's length");
  std::string bytes(static_cast<size_t>(size), '\0');
  f.seekg(0);
  if (!f.read(bytes.data(), size)) fail("read error");
  if (bytes.size() < 3 * sizeof(int32_t))
    fail("truncated header (" + std::to_string(bytes.size()) + " bytes, the three int32 dimensions need 12)");
  int32_t dims[3];
  std::memcpy(dims, bytes.data(), sizeof dims);
  for (int a = 0; a < 3; ++a)
    if (dims[a] < 1 || dims[a] > kMerlMaxAxis)
      fail("header dimension " + std::to_string(a) + " is " + std::to_string(dims[a]) + " (expected 1.." +
           std::to_string(kMerlMaxAxis) + "; the database uses 90 90 180)");
  MerlData d;
  d.thetaHalfRes = dims[0];
  d.thetaDiffRes = dims[1];
  d.phiDiffRes = dims[2];
  const uint64_t n = d.nodeCount();
  const uint64_t expected = sizeof dims + 3 * n * sizeof(double);
  if (bytes.size() != expected)
    fail("header says " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" + std::to_string(dims[2]) +
         " (3 channels, " + std::to_string(expected) + " bytes) but the file has " + std::to_string(bytes.size()) +
         " bytes" + (bytes.size() < expected ? " (truncated)" : ""));
  d.values.resize(3 * n);
  const char* p = bytes.data() + sizeof dims;
  for (size_t s = 0; s < 3 * n; ++s) {
    double v;
    std::memcpy(&v, p + s * sizeof(double), sizeof v);
    const int c = static_cast<int>(s / n);
    const size_t node = s % n;
    auto where = [&] {
      const int k = int(node % d.phiDiffRes), j = int(node / d.phiDiffRes % d.thetaDiffRes),
                i = int(node / (size_t(d.phiDiffRes) * d.thetaDiffRes));
      return "value " + std::to_string(s) + " (channel " + std::to_string(c) + ", theta_h " + std::to_string(i) +
             ", theta_d " + std::to_string(j) + ", phi_d " + std::to_string(k) + ")";
    };
    if (!std::isfinite(v)) fail(where() + " is not finite");
    if (v < 0.0) {
      if (!clampNegative)
        fail(where() + " is negative (" + std::to_string(v) +
             "); set <boolean name=\"clamp_negative\" value=\"true\"/> to read negative entries as 0");
      v = 0.0;
    }
    const double scaled = v * kMerlScale[c];
    if (!(scaled < 3.0e38)) fail(where() + " overflows a float");
    d.values[s] = static_cast<float>(scaled);
  }
  d.contentHash = fnv1a64(bytes.data(), bytes.size());
  return d;
}

void writeMerlFile(const std::string& path, const MerlData& data) {
  const size_t n = data.nodeCount();
  if (data.values.size() != 3 * n) throw Error("writeMerlFile " + path + ": value count does not match the dimensions");
  const int32_t dims[3] = {data.thetaHalfRes, data.thetaDiffRes, data.phiDiffRes};
  std::string bytes(reinterpret_cast<const char*>(dims), sizeof dims);
  bytes.resize(sizeof dims + 3 * n * sizeof(double));
  char* p = &bytes[sizeof dims];
  for (size_t s = 0; s < 3 * n; ++s) {
    const double v = double(data.values[s]) / kMerlScale[s / n];
    std::memcpy(p + s * sizeof(double), &v, sizeof v);
  }
  writeFileAtomically(path, bytes);
}

}  // namespace rc
