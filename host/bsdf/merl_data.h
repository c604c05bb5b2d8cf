#pragma once
// Tabulated isotropic BRDFs in the MERL binary format (Matusik et al. 2003, "A Data-Driven
// Reflectance Model"), the layout of the MERL/MIT database files:
//   int32 n_θh, n_θd, n_φd (90, 90, 180 in the database) |
//   double[3][n_θh][n_θd][n_φd] (red, green, blue; φ_d fastest), host byte order (little-endian).
// Stored values times the format's per-channel scale (1/1500, 1.15/1500, 1.66/1500) are f_r in
// 1/sr. The axes are Rusinkiewicz's half/difference angles: θ_h indexed by the square-root map
// i = sqrt(θ_h / (π/2))·n_θh, θ_d linearly over [0, π/2], φ_d linearly over [0, π) — the other half
// [π, 2π) is the same data by reciprocity (swapping ω_i and ω_o adds π to φ_d).
//
// Node (i, j, k) holds f at θ_h = (i/n_θh)²·π/2, θ_d = j/n_θd·π/2, φ_d = k/n_φd·π: the bins' lower
// edges, where the database's reference reader (which truncates the continuous index) returns
// exactly that entry. lookup() interpolates trilinearly between those nodes (see merl.cpp for why).
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace rc {

inline constexpr double kMerlScale[3] = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};

struct HalfDiffAngles {
  double thetaHalf = 0, thetaDiff = 0, phiDiff = 0;  // φ_d folded into [0, π)
};

// Rusinkiewicz's coordinates of the pair (ω_i, ω_o) (local frame, z = normal). Symmetric in its
// arguments after the fold of φ_d.
HalfDiffAngles halfDiffAngles(const Vec3& wi, const Vec3& wo);
// The pair (ω_i, ω_o) with φ_h = 0 for given half/difference angles (inverse of the above).
void directionsFromHalfDiff(double thetaHalf, double thetaDiff, double phiDiff, Vec3* wi, Vec3* wo);

struct MerlData {
  int thetaHalfRes = 90, thetaDiffRes = 90, phiDiffRes = 180;
  // f_r in 1/sr (scale applied), [channel][θh][θd][φd].
  std::vector<float> values;
  uint64_t contentHash = 0;  // FNV-1a of the file's bytes (0 for data made in memory)

  size_t nodeCount() const { return size_t(thetaHalfRes) * thetaDiffRes * phiDiffRes; }
  size_t index(int c, int i, int j, int k) const {
    return ((size_t(c) * thetaHalfRes + i) * thetaDiffRes + j) * phiDiffRes + k;
  }
  // Node angles (see the header comment).
  double nodeThetaHalf(int i) const;
  double nodeThetaDiff(int j) const;
  double nodePhiDiff(int k) const;
  // f_r at the given angles, trilinear between nodes; θ_h, θ_d past the last node hold its value,
  // φ_d wraps around (period π).
  Color lookup(const HalfDiffAngles& a) const;
};

// Largest axis length accepted from a header: bounds the allocation before the file length is
// compared with it.
inline constexpr int kMerlMaxAxis = 4096;

// Reads and validates a MERL file. Throws rc::Error naming `path` for: a missing/unreadable file,
// a short header, non-positive or oversized dimensions, a length that differs from what the header
// implies, NaN/infinite values, and negative values — unless `clampNegative`, where they become 0
// (some databases mark unmeasured bins with negative numbers).
MerlData readMerlFile(const std::string& path, bool clampNegative);
// Writes `data` (f_r divided by the scale again) atomically; throws rc::Error on failure.
void writeMerlFile(const std::string& path, const MerlData& data);

}  // namespace rc
