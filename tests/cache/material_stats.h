#pragma once
// The statistics' entry of one material (RenderStats "materials": name, technique, sh_order, ...).
#include <gtest/gtest.h>

#include <string>

#include "render/integrator.h"

namespace rc::test {

// The text of material `name`'s JSON object in the statistics, "" (and a test failure) when absent.
inline std::string materialEntry(const RenderStats& stats, const std::string& name) {
  std::string materials;
  for (const auto& [key, value] : stats.json)
    if (key == "materials") materials = value;
  const size_t at = materials.find("\"name\": \"" + name + "\"");
  if (at == std::string::npos) {
    ADD_FAILURE() << "no material '" << name << "' in " << materials;
    return "";
  }
  return materials.substr(at, materials.find('}', at) - at);
}

}  // namespace rc::test
