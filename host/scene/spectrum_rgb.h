#pragma once
// <spectrum> values in RGB mode, as Mitsuba 3's RGB variants convert them.
#include <vector>

#include "core/math.h"

namespace rc {

// Wavelength (nm, increasing) → value pairs to linear sRGB. Reflectances: bounded = true, d65 = true;
// emitters: bounded = false, d65 = false; unbounded non-emitter values (η, k): false, true.
Color spectrumToRgb(const std::vector<double>& wavelengths, const std::vector<double>& values, bool bounded, bool d65);
// A constant spectrum given to an emitter.
Color uniformEmitterSpectrumRgb(double value);

}  // namespace rc
