#pragma once
// Geometry of the BRDF×cos coefficient tables (host/sh/batches.h, BrdfDotBatch): where the ω_o
// grid nodes lie and how a table is looked up. The CPU lookup here follows the same contract as
// rc::ref::brdfDot and the brdf_dot kernel; it exists so that this folder can test its tables
// on its own and so that host code can fetch F(ω_o) without building a batch.
#include <vector>

#include "core/math.h"
#include "rc_types.h"

namespace rc {

// One-sided BSDFs are black at exactly ω_o.z = 0, but the lobe has a finite, non-zero limit as
// ω_o approaches the horizon. Nodes on the horizon therefore hold the lobe at cos θ_o = this
// value (θ_o ≈ 89.94°), i.e. the limit, so the lookup does not fall to zero across the last cell.
constexpr float kGrazingCos = 1e-3f;

// 1-D isotropic node t of T: ω_o in the xz-plane at parabolic radius x_t = t/(T−1), θ = 2·atan(x).
Vec3 isotropicNodeDirection(int t, int T);
// 2-D node (ix, iy) of S×S over the parabolic map; nodes outside the unit disk give the horizon
// direction of the same azimuth.
Vec3 anisotropicNodeDirection(int ix, int iy, int S);

// F(ω_o) = the table's coefficient vector at ω_o, [3][order²] in double (zero for ω_o.z ≤ 0).
// `data` points at the table's first float (i.e. flat array + table.offset).
void lookupTable(const RcBrdfTable& table, const float* data, const Vec3& wo, std::vector<double>& out);

// Rotation about z by angle alpha of a [3][order²] vector, same direction convention as
// sh::rotateZ (coefficients of f(R_z(alpha)⁻¹ ω)). Kept local so the lookup is self-contained.
void rotateAboutZ(int order, double alpha, const double* in, double* out);

// Number of floats of a table of this kind/order/res.
size_t tableFloatCount(int kind, int order, int res);

}  // namespace rc
