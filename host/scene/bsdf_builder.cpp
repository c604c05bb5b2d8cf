// <bsdf>: properties, nested BSDFs (or refs) and textured parameters handed to the BSDF factory
// (host/bsdf); a texture that scales the whole BSDF wraps it (bsdf/textured.h).
#include <algorithm>
#include <string>

#include "bsdf/bsdf_factory.h"
#include "bsdf/plugins.h"
#include "bsdf/textured.h"
#include "scene/loader.h"

namespace rc {

namespace {
// A BSDF evaluates its nested BSDFs on every call, so <ref>s to BSDFs that themselves hold refs
// form a DAG whose evaluation visits every path: 40 blends of two refs to the previous one are
// 2^40 evaluations per shading point. Real materials nest a handful (twosided, blend, mask).
constexpr uint64_t kMaxBsdfTreeNodes = 4096;
}  // namespace

// The nested BSDFs and the textured parameters of a <bsdf>: <texture name="p"> or <ref name="p"
// id="a texture"/> (a null texture: one lenient mode left out).
void Loader::collectBsdfChildren(const std::shared_ptr<XmlFile>& file, const Element& e, std::vector<BsdfPtr>& nested,
                                 std::vector<std::pair<pugi::xml_node, TexturePtr>>& textures) {
  for (const pugi::xml_node& child : e.children) {
    const std::string tag = child.name();
    if (tag == "bsdf") {
      nested.push_back(buildBsdf(file, child));
    } else if (tag == "texture") {
      if (std::string(child.attribute("name").value()).empty() && e.type != "bumpmap")
        throw LocatedError(whereOf(*file, child) + ": a <texture> inside a <bsdf> needs the parameter's 'name'");
      textures.emplace_back(child, buildTexture(file, child));
    } else if (tag == "ref") {
      const Named& n = resolveRef(file, child);
      if (n.kind == Kind::Texture && (!std::string(child.attribute("name").value()).empty() || e.type == "bumpmap")) {
        textures.emplace_back(child, n.texture);
        continue;
      }
      if (n.kind != Kind::Bsdf || !n.bsdf)
        throw LocatedError(whereOf(*file, child) + ": id '" + std::string(child.attribute("id").value()) +
                           "' (defined at " + n.where + ") is not a bsdf");
      nested.push_back(n.bsdf);
    } else {
      unexpectedChild(e, child);
    }
  }
}

// Depth and evaluation size of a BSDF over its nested ones, refused past the bounds.
Loader::BsdfTreeSize Loader::bsdfTreeOf(const Element& e, const std::vector<BsdfPtr>& nested) const {
  BsdfTreeSize tree;
  for (const BsdfPtr& child : nested) {
    auto it = bsdfTreeSizes_.find(child.get());
    const BsdfTreeSize sub = it == bsdfTreeSizes_.end() ? BsdfTreeSize{} : it->second;
    tree.depth = std::max(tree.depth, sub.depth + 1);
    tree.nodes = std::min(tree.nodes + sub.nodes, kMaxBsdfTreeNodes + 1);  // saturates: no overflow
  }
  if (tree.depth > kMaxElementDepth)
    e.fail("BSDFs nested deeper than " + std::to_string(kMaxElementDepth) + " levels (counting those reached by <ref>)");
  if (tree.nodes > kMaxBsdfTreeNodes)
    e.fail("one evaluation of this BSDF would visit more than " + std::to_string(kMaxBsdfTreeNodes) +
           " nested BSDFs (<ref>s to BSDFs that hold <ref>s multiply)");
  return tree;
}

// Puts each textured parameter into e.props (its mean stands in) and sorts the textures into the
// whole-BSDF factor (bsdf/textured.h) and those the BSDF evaluates per point (Bsdf::at).
void Loader::applyBsdfTextures(const std::shared_ptr<XmlFile>& file, Element& e,
                               const std::vector<std::pair<pugi::xml_node, TexturePtr>>& textures, TexturePtr& factor,
                               BsdfTextures& perPoint) {
  for (const auto& [child, texture] : textures) {
    // A bumpmap takes its one texture under any name (Mitsuba 3).
    const std::string name = e.type == "bumpmap" ? kBumpMapTextureParameter : child.attribute("name").value();
    if (e.props.has(name) || (factor && isBsdfFactorParameter(e.type, name)))
      throw LocatedError(whereOf(*file, child) + ": parameter '" + name + "' is given more than once");
    // rcache plans a material from its textures over uv (a roughness' range, a fingerprint); a
    // mesh attribute has no uv lookup, so it is taken where it only scales the whole BSDF.
    // A volume texture (of the world position) likewise.
    const bool pointwise = texture && (!texture->meshAttribute().empty() || texture->readsPosition());
    const bool standIn = pointwise && !isBsdfFactorParameter(e.type, name);
    if (standIn)
      unsupported(whereOf(*file, child) + ": a " + (texture->readsPosition() ? "volume" : "mesh_attribute") +
                  " texture on parameter '" + name + "' of <bsdf type=\"" + e.type +
                  "\"> is not supported (only on diffuse 'reflectance' and conductor 'specular_reflectance'); "
                  "lenient: its stand-in value");
    Property p;
    p.line = file->lineOf(child);
    p.type = Property::Type::Rgb;
    p.vec = Color(1.0f);
    if (texture && isBsdfFactorParameter(e.type, name)) {
      factor = texture;  // the BSDF is built with this parameter 1 and scaled per point
    } else {
      if (texture && isBsdfTextureParameter(e.type, name) && !standIn)
        perPoint[name] = texture;  // evaluated per point by the BSDF (Bsdf::at); the mean stands in
      else if (texture && !standIn)
        unsupported(whereOf(*file, child) + ": a texture on parameter '" + name + "' of <bsdf type=\"" + e.type +
                    "\"> is not supported (textured parameters: diffuse 'reflectance', conductor "
                    "'specular_reflectance', the roughness of rough conductors/dielectrics, plastic "
                    "reflectances, mask 'opacity', principled); lenient: its mean value");
      const Color mean = texture ? texture->mean() : Color(0.5f);
      p.vec = mean;
      if (mean.r == mean.g && mean.g == mean.b) {  // grey: also valid for float parameters
        p.type = Property::Type::Float;
        p.number = mean.r;
      } else if (perPoint.count(name) && !isBsdfColorTextureParameter(e.type, name)) {
        p.type = Property::Type::Float;  // a scalar parameter: Mitsuba's eval_1 of the texture
        p.number = luminance(mean);
      }
    }
    e.props.set(name, p);
  }
}

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
  std::vector<std::pair<pugi::xml_node, TexturePtr>> textures;
  collectBsdfChildren(file, e, nested, textures);

  const BsdfTreeSize tree = bsdfTreeOf(e, nested);

  BsdfPtr bsdf;
  if (!isKnownBsdfType(e.type)) {
    unsupported(e.where() + ": unknown plugin '" + e.type + "'");
    // Lenient mode: keep the scene renderable with Mitsuba's default material in its place.
    bsdf = defaultBsdf();
    registerId(e, Kind::Bsdf, bsdf);
    return bsdf;
  }
  TexturePtr factor;
  BsdfTextures perPoint;
  applyBsdfTextures(file, e, textures, factor, perPoint);
  bsdf = e.located([&] { return createBsdf(e.props, nested, e.id, perPoint); });
  if (!bsdf) e.fail("the BSDF factory returned nothing");
  checkUnused(e);
  if (factor) bsdf = makeTexturedBsdf(bsdf, factor);
  bsdfTreeSizes_[bsdf.get()] = tree;
  std::vector<std::string> attributes;
  for (const BsdfPtr& child : nested)
    if (auto it = meshAttributesRead_.find(child.get()); it != meshAttributesRead_.end())
      attributes.insert(attributes.end(), it->second.begin(), it->second.end());
  if (factor && !factor->meshAttribute().empty()) attributes.push_back(factor->meshAttribute());
  if (!attributes.empty()) meshAttributesRead_[bsdf.get()] = std::move(attributes);
  registerId(e, Kind::Bsdf, bsdf);
  return bsdf;
}

BsdfPtr Loader::defaultBsdf(bool emitterShape) {
  BsdfPtr& bsdf = defaultBsdf_[emitterShape ? 1 : 0];
  if (!bsdf) {
    Properties props;
    props.pluginType = "diffuse";
    props.location = "(default material)";
    Property reflectance;
    reflectance.type = Property::Type::Rgb;
    reflectance.vec = Color(emitterShape ? 0.0f : 0.5f);
    props.set("reflectance", reflectance);
    bsdf = createBsdf(props, {}, emitterShape ? "default-emitter-black" : "default-diffuse");
  }
  return bsdf;
}

// Mitsuba evaluates a mesh_attribute through the shape it shades: a shape without the attribute
// (or not a mesh) fails there at render time, here at load.
void Loader::checkMeshAttributes(const Element& shape, const BsdfPtr& bsdf, const Mesh* mesh) const {
  const auto it = meshAttributesRead_.find(bsdf.get());
  if (it == meshAttributesRead_.end()) return;
  for (const std::string& name : it->second) {
    if (!mesh) shape.fail("its bsdf reads the mesh attribute '" + name + "', and a " + shape.type + " has no attributes");
    bool found = false;
    std::string have;
    for (const MeshAttribute& a : mesh->attributes) {
      found = found || a.name == name;
      have += (have.empty() ? "" : ", ") + a.name;
    }
    if (!found)
      shape.fail("its bsdf reads the mesh attribute '" + name + "', which the mesh does not have (" +
                 (have.empty() ? std::string("it has none") : "it has " + have) + ")");
  }
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
