// <shape type="shapegroup"> and <shape type="instance"> (Mitsuba's src/shapes/shapegroup.cpp,
// instance.cpp): a group holds shapes that are not rendered themselves; each instance places a
// copy of them with its to_world (scene/instance_placement.h).
#include <cmath>

#include "scene/instance_placement.h"
#include "scene/loader.h"

namespace rc {

namespace {

// The primitives all instances together may place: each copy costs memory per primitive (its
// geometry, or for an sdfgrid its voxels' BVH leaves; bench/RESULTS.md "sdfgrid and instances"),
// so a small file naming one large group many times is stopped here, before the copies are made,
// rather than by the allocator. 2^25 is a few GB.
constexpr size_t kMaxInstancedPrimitives = size_t(1) << 25;

}  // namespace

int Loader::buildShapeGroup(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  const Element e = parseElement(file, node);
  ShapeLists group;
  for (const pugi::xml_node& child : e.children) {
    if (std::string(child.name()) != "shape")
      throw LocatedError(whereOf(*file, child) + ": a shapegroup holds only shapes, not <" + child.name() + ">");
    buildShapeInto(file, child, group, &e);
  }
  checkUnused(e);
  const int index = static_cast<int>(shapeGroups_.size());
  shapeGroups_.push_back(std::move(group));
  registerId(e, Kind::ShapeGroup).shapeGroup = index;
  return index;
}

void Loader::buildInstance(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  const Element e = parseElement(file, node);
  int group = -1;
  for (const pugi::xml_node& child : e.children) {
    const std::string tag = child.name();
    const bool inlineGroup = tag == "shape" && std::string(child.attribute("type").value()) == "shapegroup";
    if (tag != "ref" && !inlineGroup)
      throw LocatedError(whereOf(*file, child) + ": an instance holds only a shapegroup (a <ref> to one, or one inline)");
    if (group >= 0) throw LocatedError(whereOf(*file, child) + ": an instance takes one shapegroup, this is the second");
    if (inlineGroup) {
      group = buildShapeGroup(file, child);
      continue;
    }
    const Named& n = resolveRef(file, child);
    if (n.kind != Kind::ShapeGroup)
      throw LocatedError(whereOf(*file, child) + ": id '" + std::string(child.attribute("id").value()) +
                         "' (defined at " + n.where + ") is not a shapegroup");
    group = n.shapeGroup;
  }
  if (group < 0) e.fail("an instance needs a shapegroup: <ref id=\"...\"/> naming one");
  const Mat4 toWorld = e.transform("to_world");
  const float det = glm::determinant(Mat3(toWorld));
  if (!(std::fabs(det) > 0.0f) || !std::isfinite(det)) e.failParam("to_world", "the instance's to_world is singular");
  instancedPrimitives_ += instancePrimitives(shapeGroups_[group]);
  if (instancedPrimitives_ > kMaxInstancedPrimitives)
    e.fail("the instances place more than " + std::to_string(kMaxInstancedPrimitives) +
           " primitives in all (rcache copies each instance's geometry)");
  const std::string name = (e.id.empty() ? anonymousName(e.type) : e.id) + " (" + file->location(node) + ")";
  e.located([&] { placeInstance(shapeGroups_[group], toWorld, name, scene_); });
  checkUnused(e);
  registerId(e, Kind::Shape);
}

}  // namespace rc
