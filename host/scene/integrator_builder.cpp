// <integrator type="path|rcache">: the shared path parameters typed, every parameter kept raw in
// IntegratorSettings::params (the rcache integrator parses its own: a, rays, order, ...).
#include "scene/loader.h"

namespace rc {

void Loader::buildIntegrator(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  const Element e = parseElement(file, node);
  for (const pugi::xml_node& child : e.children) unexpectedChild(e, child);
  if (e.type.empty()) e.fail("missing attribute 'type'");
  if (e.type != "path" && e.type != "rcache") {
    unsupported(e.where() + ": unknown plugin '" + e.type + "'");
    return;
  }
  if (integrators_++ > 0) e.fail("only one <integrator> is allowed");
  IntegratorSettings& s = scene_.integrator;
  s.type = e.type;
  s.maxDepth = e.located([&] { return e.props.getInt("max_depth", -1); });
  s.rrDepth = e.located([&] { return e.props.getInt("rr_depth", 5); });
  s.hideEmitters = e.located([&] { return e.props.getBool("hide_emitters", false); });
  if (s.maxDepth < -1) e.failParam("max_depth", "'max_depth' must be -1 (unbounded) or >= 0");
  if (s.rrDepth <= 0) e.failParam("rr_depth", "'rr_depth' must be positive");
  s.params = e.raw;
  for (const auto& kv : e.raw) s.paramWhere[kv.first] = e.whereParam(kv.first);
  if (e.type == "path") {
    checkUnused(e);
  } else {
    // rcache parameters beyond the three above are validated by the rcache integrator when it
    // starts (it knows its own names); only transforms are certainly misplaced here.
    for (const auto& kv : e.transforms) unsupported(e.whereParam(kv.first) + ": unsupported parameter '" + kv.first + "'");
  }
}

}  // namespace rc
