#pragma once
// Participating media (Mitsuba 3 src/media/{homogeneous,heterogeneous}.cpp,
// src/phase/{isotropic,hg}.cpp), as the loader builds them (scene/medium_builder.cpp); the
// volumetric path tracer (render/volpath.h) samples them (render/medium_tracking.h).
//
// <medium type="homogeneous"> and <medium type="heterogeneous">
// | parameter               | type                 | default   | meaning                               |
// |-------------------------|----------------------|-----------|---------------------------------------|
// | sigma_t                 | float, rgb or volume | 1         | extinction per scene unit, ≥ 0        |
// | albedo                  | float, rgb or volume | 0.75      | single-scattering albedo in [0, 1]    |
// | scale                   | float                | 1         | multiplies sigma_t, ≥ 0               |
// | sample_emitters         | boolean              | true      | light-sample from scattering points   |
// | has_spectral_extinction | boolean              | true      | Mitsuba's sampling choice; rcache always weights per channel (the same mean where sigma_t is grey) |
// | <phase>                 | isotropic or hg (g in (−1, 1), default 0.8) | isotropic |        |
// A homogeneous medium's extinction is one value everywhere: Mitsuba samples distances with the
// majorant sigma_t at the origin, so a sigma_t volume is read there too.
// A heterogeneous medium's extinction is scale · sigma_t(p) inside the sigma_t volume's bounds
// (its to_world's unit cube; a float or rgb sigma_t is a constvolume over [0,1]³) and nothing
// outside them; its majorant is scale · the largest value of any channel of sigma_t.
#include <string>

#include "core/math.h"
#include "texture/volume.h"

namespace rc {

struct PhaseFunction {
  enum class Type { Isotropic, HenyeyGreenstein };
  Type type = Type::Isotropic;
  float g = 0.0f;  // HG asymmetry: > 0 scatters forward
};

// A heterogeneous medium is tracked by null collisions against its majorant, about majorant · d
// of them over a distance d. The loader refuses a medium whose majorant times its bounds' diagonal
// exceeds this: every ray across it would cost as many density lookups, a render that does not
// finish (rcache has no majorant grid to make a dense medium cheaper).
constexpr double kMaxCollisionsAcross = 1e5;

struct Medium {
  std::string name;  // id or "homogeneous#n", and its file:line, for messages
  bool homogeneous = true;
  Color sigmaT{1.0f};  // homogeneous: extinction per scene unit, scale applied
  // Heterogeneous: extinction scale · density(p) within density's bounds, at most `majorant`.
  VolumePtr density;
  float scale = 1.0f;
  float majorant = 0.0f;
  VolumePtr albedo;  // single-scattering albedo at a world point
  PhaseFunction phase;
  bool sampleEmitters = true;

  Color extinctionAt(const Vec3& p) const { return homogeneous ? sigmaT : scale * density->eval(p); }
};

// The media on either side of a shape's surface (Mitsuba's interior/exterior): indices into
// Scene::media, −1 for none (vacuum).
struct MediumInterface {
  int interior = -1, exterior = -1;
  bool transition() const { return interior >= 0 || exterior >= 0; }
};

}  // namespace rc
