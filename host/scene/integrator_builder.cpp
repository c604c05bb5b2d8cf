// <integrator type="...">: the type, its parameters typed and use-tracked, and where they were
// written. The scene builder knows no integrator names: the integrator registry
// (app/integrator_registry.h) resolves the type, reads the parameters and reports unknown types and
// unused parameters with the locations kept here. An integrator holding another integrator (a
// wrapper such as Mitsuba's `aov` or `moment`) is read as the one it holds: rcache renders the
// inner integrator's image, and the wrapper's own outputs are not produced.
#include "core/error.h"
#include "scene/integrator_params.h"
#include "scene/loader.h"
#include "scene/param_reader.h"

namespace rc {

void Loader::buildIntegrator(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  if (integrators_++ > 0) parseElement(file, node).fail("only one <integrator> is allowed");
  IntegratorSettings& s = scene_.integrator;
  pugi::xml_node current = node;
  for (;;) {
    const Element e = parseElement(file, current);
    if (e.type.empty()) e.fail("missing attribute 'type'");
    pugi::xml_node inner;
    for (const pugi::xml_node& child : e.children) {
      if (std::string(child.name()) != "integrator" || inner) unexpectedChild(e, child);
      inner = child;
    }
    if (inner) {
      s.wrappers.push_back(e.type);
      current = inner;
      continue;
    }
    for (const auto& kv : e.transforms) unsupported(e.whereParam(kv.first) + ": unsupported parameter '" + kv.first + "'");
    s.type = e.type;
    s.props = e.props;
    // Filled now for code that makes integrators without the registry (tests, benchmarks); read
    // from a copy so that the registry still sees which parameters its integrator leaves unused.
    const Properties unmarked = e.props;
    ParamReader in(&unmarked);
    try {
      readPathParams(in, s);
    } catch (const Error& err) {
      e.failParam(in.names().back(), err.what());  // the last parameter read is the one that failed
    }
    s.where = e.where();
    s.paramWhere.clear();
    for (const auto& kv : e.raw) s.paramWhere[kv.first] = e.whereParam(kv.first);
    return;
  }
}

}  // namespace rc
