// <bsdf>: properties and nested BSDFs (or refs) handed to the BSDF factory (host/bsdf).
#include "bsdf/bsdf_factory.h"
#include "scene/loader.h"

namespace rc {

BsdfPtr Loader::buildBsdf(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  Element e = parseElement(file, node);
  if (e.type.empty()) e.fail("missing attribute 'type'");
  // A BSDF's data file (merl's measured table) is found like a mesh: relative to the scene file.
  if (auto it = e.raw.find("filename");
      it != e.raw.end() && !it->second.empty() && node.find_child_by_attribute("string", "name", "filename")) {
    Property resolved;
    resolved.type = Property::Type::String;
    resolved.text = resolvePath(e, it->second);
    resolved.line = e.props.lineOf("filename");
    e.props.set("filename", resolved);
  }
  std::vector<BsdfPtr> nested;
  for (const pugi::xml_node& child : e.children) {
    const std::string tag = child.name();
    if (tag == "bsdf") {
      nested.push_back(buildBsdf(file, child));
    } else if (tag == "ref") {
      const Named& n = resolveRef(file, child);
      if (n.kind != Kind::Bsdf || !n.bsdf)
        throw LocatedError(whereOf(*file, child) + ": id '" + std::string(child.attribute("id").value()) +
                           "' (defined at " + n.where + ") is not a bsdf");
      nested.push_back(n.bsdf);
    } else {
      unexpectedChild(e, child);
    }
  }

  BsdfPtr bsdf;
  if (!isKnownBsdfType(e.type)) {
    unsupported(e.where() + ": unknown plugin '" + e.type + "'");
    // Lenient mode: keep the scene renderable with Mitsuba's default material in its place.
    bsdf = defaultBsdf();
    registerId(e, Kind::Bsdf, bsdf);
    return bsdf;
  }
  bsdf = e.located([&] { return createBsdf(e.props, nested, e.id); });
  if (!bsdf) e.fail("the BSDF factory returned nothing");
  checkUnused(e);
  registerId(e, Kind::Bsdf, bsdf);
  return bsdf;
}

BsdfPtr Loader::defaultBsdf() {
  if (!defaultBsdf_) {
    // A shape without a material is diffuse with reflectance 0.5, as in Mitsuba 3.
    Properties props;
    props.pluginType = "diffuse";
    props.location = "(default material)";
    Property reflectance;
    reflectance.type = Property::Type::Rgb;
    reflectance.vec = Color(0.5f);
    props.set("reflectance", reflectance);
    defaultBsdf_ = createBsdf(props, {}, "default-diffuse");
  }
  return defaultBsdf_;
}

int Loader::bsdfIndex(const BsdfPtr& bsdf) {
  auto it = bsdfIndices_.find(bsdf.get());
  if (it != bsdfIndices_.end()) return it->second;
  const int index = static_cast<int>(scene_.bsdfs.size());
  scene_.bsdfs.push_back(bsdf);
  bsdfIndices_[bsdf.get()] = index;
  return index;
}

}  // namespace rc
