#pragma once
// Participating media (Mitsuba 3 src/media/homogeneous.cpp, src/phase/{isotropic,hg}.cpp), as the
// loader builds them (scene/medium_builder.cpp); the volumetric path tracer (render/volpath.h)
// samples them.
//
// <medium type="homogeneous">
// | parameter               | type                 | default   | meaning                               |
// |-------------------------|----------------------|-----------|---------------------------------------|
// | sigma_t                 | float, rgb or volume | 1         | extinction per scene unit, ≥ 0        |
// | albedo                  | float, rgb or volume | 0.75      | single-scattering albedo in [0, 1]    |
// | scale                   | float                | 1         | multiplies sigma_t, ≥ 0               |
// | sample_emitters         | boolean              | true      | light-sample from scattering points   |
// | has_spectral_extinction | boolean              | true      | Mitsuba's sampling choice; the mean is the same either way |
// | <phase>                 | isotropic or hg (g in (−1, 1), default 0.8) | isotropic |        |
// A homogeneous medium's extinction is one value everywhere: Mitsuba samples distances with the
// majorant sigma_t at the origin, so a sigma_t volume is read there too.
#include <string>

#include "core/math.h"
#include "texture/volume.h"

namespace rc {

struct PhaseFunction {
  enum class Type { Isotropic, HenyeyGreenstein };
  Type type = Type::Isotropic;
  float g = 0.0f;  // HG asymmetry: > 0 scatters forward
};

struct Medium {
  std::string name;      // id or "homogeneous#n", and its file:line, for messages
  Color sigmaT{1.0f};    // extinction per scene unit, scale applied
  VolumePtr albedo;      // single-scattering albedo at a world point
  PhaseFunction phase;
  bool sampleEmitters = true;
};

// The media on either side of a shape's surface (Mitsuba's interior/exterior): indices into
// Scene::media, −1 for none (vacuum).
struct MediumInterface {
  int interior = -1, exterior = -1;
  bool transition() const { return interior >= 0 || exterior >= 0; }
};

}  // namespace rc
