#pragma once
// Order-3 records (irradiance caches: their Lambertian lookups are RadianceCache::cosineIrradiance)
// get the irradiance at their own normal from their rays exactly, not from bands 0..2 alone.
//
// E(n) from bands 0..2 leaves out the clamped cosine's bands 4, 6, ... (Â_4 = π/24 of Â_0 = π).
// That loss does not average out: it is a property of the light, not of the noise, so a sky with
// structure along the elevation (a bright ring, a horizon) is shaded a few percent too dark or
// too bright at every spp (bench/RESULTS.md, ninth session). Ward's irradiance cache stores the
// cosine-weighted sum of its rays, which has no such loss; here the record's band-0 coefficient
// takes the difference, so that E(n_record) equals that sum and every other normal keeps the bands'
// variation around it (only the change of the left-out bands between n_record and n remains). The
// record's file format, rotation, gradients and interpolation are unchanged.
#include "sh/batches.h"

namespace rc {

// For each record of `rays` (order 3): Λ_00 += (E_rays − E_bands)/(Â_0·y_00) per channel, with
// E_rays = 2π/S Σ L_s cos θ_s over the finite samples (the projection drops the others) and
// E_bands = Σ_{l≤2} Â_l Λ_lm y_lm(n) at the record's normal (local +z).
void matchCosineIrradianceAtNormal(const ProjectBatch& rays, ProjectResult& projected);

}  // namespace rc
