#pragma once
// Writes reflectance models into the MERL layout (bsdf/merl_data.h): the test data of the merl
// BSDF. An analytic BSDF tabulated here and read back by the merl plugin must render like the
// analytic BSDF up to the table's discretisation error, which is what the twin tests check.
#include <functional>

#include "bsdf/bsdf.h"
#include "bsdf/merl_data.h"

namespace rc {

// f_r(ω_i, ω_o) in 1/sr, both directions above the surface.
using BrdfFunction = std::function<Color(const Vec3& wi, const Vec3& wo)>;

// Every node's value (node angles of MerlData), 0 where one direction is below the horizon.
MerlData tabulateMerl(const BrdfFunction& f, int thetaHalfRes = 90, int thetaDiffRes = 90, int phiDiffRes = 180);
// f_r of an isotropic BSDF: eval(ω_o, ω_i) / cos θ_i. Throws rc::Error for an anisotropic one.
BrdfFunction brdfOf(const Bsdf& bsdf);

// A hand-made reflectance no analytic model of host/bsdf has: a Lambertian base plus a
// retro-reflective lobe around ω_i = ω_o, f = kd/π + ks·exp(−(θ_d/σ)²) (θ_d is half the angle
// between ω_i and ω_o). Its peak moves with the view in ω_i but sits at θ_d = 0 in the table.
struct RetroReflectiveLobe {
  Color diffuse{0.15f, 0.2f, 0.25f};  // kd
  Color retro{0.9f, 0.7f, 0.5f};      // ks (1/sr)
  float width = 0.15f;                // σ in radians of θ_d
  Color operator()(const Vec3& wi, const Vec3& wo) const;
};

}  // namespace rc
