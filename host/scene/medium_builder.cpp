// <medium type="homogeneous"> and <medium type="heterogeneous"> with its <phase> (parameters: scene/medium.h), and the references to
// media from shapes (interior, exterior) and the sensor (medium).
#include <cmath>
#include <cstdio>

#include "scene/loader.h"

namespace rc {

namespace {

PhaseFunction buildPhase(Loader& loader, const Element& e) {
  for (const pugi::xml_node& child : e.children) loader.unexpectedChild(e, child);
  PhaseFunction phase;
  if (e.type == "isotropic") {
    phase.type = PhaseFunction::Type::Isotropic;
  } else if (e.type == "hg") {
    phase.type = PhaseFunction::Type::HenyeyGreenstein;
    phase.g = e.located([&] { return e.props.getFloat("g", 0.8f); });
    if (!(std::fabs(phase.g) < 1.0f))
      e.failParam("g", "the asymmetry 'g' must lie in (-1, 1), got " + std::to_string(phase.g));
  } else {
    e.fail("unknown phase function '" + e.type + "' (known: isotropic, hg)");
  }
  loader.checkUnused(e);
  return phase;
}

bool inUnitInterval(const Color& c) { return glm::all(glm::greaterThanEqual(c, Color(0.0f))) && glm::all(glm::lessThanEqual(c, Color(1.0f))); }

}  // namespace

int Loader::buildMedium(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  const Element e = parseElement(file, node);
  if (e.type.empty()) e.fail("missing attribute 'type'");
  if (e.type != "homogeneous" && e.type != "heterogeneous")
    e.fail("unknown medium plugin '" + e.type + "' (known: homogeneous, heterogeneous)");
  Medium m;
  m.homogeneous = e.type == "homogeneous";
  m.name = (e.id.empty() ? anonymousName(e.type) : e.id) + " (" + file->location(node) + ")";
  bool phaseGiven = false;
  std::map<std::string, VolumePtr> volumes;
  for (const pugi::xml_node& child : e.children) {
    const std::string tag = child.name();
    const std::string name = child.attribute("name").value();
    if (tag == "phase") {
      if (phaseGiven) throw LocatedError(whereOf(*file, child) + ": a medium takes one phase function, this is the second");
      m.phase = buildPhase(*this, parseElement(file, child));
      phaseGiven = true;
    } else if (tag == "volume" && (name == "albedo" || name == "sigma_t")) {
      if (volumes.count(name)) throw LocatedError(whereOf(*file, child) + ": '" + name + "' is given twice");
      volumes[name] = buildVolume(file, child);
    } else if (tag == "ref" && (name == "albedo" || name == "sigma_t")) {
      volumes[name] = resolveRefTo(file, child, Kind::Volume, "volume").volume;
    } else {
      unexpectedChild(e, child);
    }
  }
  const VolumePtr sigmaT = volumeParameter(e, "sigma_t", Color(1.0f), volumes);
  m.albedo = volumeParameter(e, "albedo", Color(0.75f), volumes);
  const float scale = e.located([&] { return e.props.getFloat("scale", 1.0f); });
  m.sampleEmitters = e.located([&] { return e.props.getBool("sample_emitters", true); });
  // Mitsuba's choice between sampling distances per channel with a spectral correction and
  // without one: the same expectation wherever sigma_t is one value, which rcache always samples.
  e.located([&] { return e.props.getBool("has_spectral_extinction", true); });
  if (!(scale >= 0.0f) || !std::isfinite(scale)) e.failParam("scale", "'scale' must be non-negative and finite");
  if (!glm::all(glm::greaterThanEqual(sigmaT->minimum(), Color(0.0f))))
    e.failParam("sigma_t", "the extinction 'sigma_t' must be non-negative");
  if (!inUnitInterval(m.albedo->minimum()) || !inUnitInterval(m.albedo->maximum()))
    e.failParam("albedo", "the 'albedo' must lie in [0, 1]");
  if (m.homogeneous) {
    // Mitsuba reads the extinction (its majorant) at the interaction's default position, the
    // origin, whatever volume gives it.
    m.sigmaT = sigmaT->eval(Vec3(0.0f)) * scale;
    if (!std::isfinite(maxComponent(m.sigmaT))) e.failParam("sigma_t", "'sigma_t' · 'scale' is not finite");
  } else {
    m.density = sigmaT;
    m.scale = scale;
    m.majorant = scale * sigmaT->largestValue();
    if (!std::isfinite(m.majorant)) e.failParam("sigma_t", "the majorant 'scale' · max 'sigma_t' is not finite");
    const Bounds3 box = sigmaT->bounds();
    const double across = double(m.majorant) * glm::length(box.hi - box.lo);
    if (m.majorant > 0.0f && !(across <= kMaxCollisionsAcross)) {
      char text[256];
      std::snprintf(text, sizeof(text), "the majorant 'scale' · max 'sigma_t' = %g over the volume's diagonal means %g expected null collisions per ray across it (at most %g): lower 'scale'",
                    m.majorant, across, kMaxCollisionsAcross);
      e.failParam("sigma_t", text);
    }
  }
  checkUnused(e);
  const int index = static_cast<int>(scene_.media.size());
  scene_.media.push_back(std::move(m));
  Named& n = registerId(e, Kind::Medium);
  n.medium = index;
  return index;
}

int Loader::mediumOf(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& child) {
  if (std::string(child.name()) == "medium") return buildMedium(file, child);
  return resolveRefTo(file, child, Kind::Medium, "medium").medium;
}

}  // namespace rc
