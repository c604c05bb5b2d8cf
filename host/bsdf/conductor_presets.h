#pragma once
// Mitsuba 3's named conductors (`material` of conductor / roughconductor: "Au", "Cu", "Al", "Ag", "Cr",
// ... and their "_palik" variants) as the RGB η and k its RGB variants render with.
#include <string>

#include "core/math.h"

namespace rc {

// False when `name` is no preset.
bool lookupConductorPreset(const std::string& name, Color* eta, Color* k);
std::string conductorPresetNames();  // comma-separated, for messages

}  // namespace rc
