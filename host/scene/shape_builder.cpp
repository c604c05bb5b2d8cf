// <shape>: obj, ply, serialized, rectangle, cube, disk as world-space meshes; sphere, cylinder,
// linearcurve, bsplinecurve and sdfgrid as analytic shapes (shapegroup and instance:
// instance_builder.cpp).
#include <cmath>

#include "core/frame.h"
#include "scene/loader.h"
#include "scene/curve_loader.h"
#include "scene/mesh_builder.h"
#include "scene/obj_loader.h"
#include "scene/ply_loader.h"
#include "scene/sdf_grid_loader.h"
#include "scene/serialized_loader.h"
#include "scene/similarity_transform.h"

namespace rc {

namespace {

// The shape's `filename`, which it cannot do without; `hint` follows the error's text.
std::string requiredFilename(const Element& e, const std::string& hint) {
  const std::string fn = e.located([&] { return e.props.getString("filename", ""); });
  if (fn.empty()) e.fail("missing parameter 'filename'" + hint);
  return fn;
}

// The analytic sphere of a <shape type="sphere">, its center and radius taken to world space.
Sphere makeSphere(const Element& e, const Mat4& toWorld, const std::string& name, bool flip, int material) {
  Sphere s;
  s.name = name;
  const Vec3 center = e.located([&] { return e.props.getVector("center", Vec3(0.0f)); });
  const float radius = e.located([&] { return e.props.getFloat("radius", 1.0f); });
  if (!(radius > 0.0f)) e.failParam("radius", "radius must be positive, got " + std::to_string(radius));
  float scale = 1.0f;
  if (!similarity(toWorld, scale))
    e.failParam("to_world", "a sphere's to_world may only rotate, translate and scale uniformly "
                            "(use an obj/ply mesh for an ellipsoid)");
  s.center = Vec3(toWorld * Vec4(center, 1.0f));
  s.radius = radius * scale;
  s.flipNormals = flip;
  s.bsdf = material;
  return s;
}

// Mitsuba's cylinder: the unit cylinder placed by to_world · translate(p0) · frame(p1 − p0) ·
// scale(radius, radius, |p1 − p0|). Parameters:
//   p0, p1        point      the axis' end points, default (0,0,0) and (0,0,1)
//   radius        float      default 1
//   flip_normals  boolean    normals toward the axis, default false
//   to_world      transform  applied after p0/p1/radius
// An open tube (no caps); a mirroring to_world flips the normals back outward, as Mitsuba does.
Cylinder makeCylinder(const Element& e, const Mat4& toWorld, const std::string& name, bool flip, int material) {
  const Vec3 p0 = e.located([&] { return e.props.getVector("p0", Vec3(0.0f)); });
  const Vec3 p1 = e.located([&] { return e.props.getVector("p1", Vec3(0.0f, 0.0f, 1.0f)); });
  const float radius = e.located([&] { return e.props.getFloat("radius", 1.0f); });
  if (!(radius > 0.0f)) e.failParam("radius", "radius must be positive, got " + std::to_string(radius));
  const float length = glm::length(p1 - p0);
  if (!(length > 0.0f)) e.failParam(e.props.has("p1") ? "p1" : "p0", "'p0' and 'p1' coincide");
  const Frame axis = Frame::fromNormal((p1 - p0) / length);
  Mat4 place(1.0f);
  place[0] = Vec4(axis.t * radius, 0.0f);
  place[1] = Vec4(axis.b * radius, 0.0f);
  place[2] = Vec4(axis.n * length, 0.0f);
  place[3] = Vec4(p0, 1.0f);
  Cylinder c;
  c.name = name;
  c.toWorld = toWorld * place;
  const float det = glm::determinant(Mat3(c.toWorld));
  if (!(std::fabs(det) > 0.0f) || !std::isfinite(det)) e.failParam("to_world", "the cylinder's to_world is singular");
  c.toObject = glm::inverse(c.toWorld);
  c.flipNormals = det < 0.0f ? !flip : flip;
  c.bsdf = material;
  return c;
}

// Mitsuba's linearcurve / bsplinecurve. Parameters:
//   filename   string     the curve file (scene/curve_loader.h)
//   to_world   transform  applied to the control points' positions; their radii are left as
//                         written (Mitsuba: "the control points' radii are invariant to this
//                         transformation")
// No flip_normals: the normal points away from the curve's axis, and rays from inside miss
// (Mitsuba culls them; so does geometry/curve_geometry's filter).
template <class Resolve>
Curve makeCurve(const Element& e, const Mat4& toWorld, const std::string& name, int material, const Resolve& resolve) {
  const std::string fn = requiredFilename(e, "");
  Curve c;
  c.name = name;
  c.basis = e.type == "linearcurve" ? CurveBasis::Linear : CurveBasis::BSpline;
  const std::string path = resolve(fn);
  CurveData data = e.located([&] { return loadCurves(path, c.basis); });
  c.points = std::move(data.points);
  c.segments = std::move(data.segments);
  for (Vec4& p : c.points) {
    const Vec4 h = toWorld * Vec4(Vec3(p), 1.0f);
    const Vec3 w = Vec3(h) / h.w;  // a point: Mitsuba divides by the projective coordinate
    if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z))
      e.failParam("to_world", "a control point of '" + fn + "' is not finite in world space");
    p = Vec4(w, p.w);
  }
  c.bsdf = material;
  return c;
}

// Mitsuba's sdfgrid. Parameters:
//   filename   string     a single-channel .vol file (scene/sdf_grid_loader.h); its bounding box is
//                         ignored: the grid spans the unit cube
//   normals    string     smooth (default) | analytic (geometry/sdf_grid_math.h)
//   to_world   transform  any invertible affine map (Mitsuba warns on rotations, which its tight
//                         voxel boxes do not follow; rcache's boxes do)
template <class Resolve>
SdfGrid makeSdfGrid(const Element& e, const Mat4& toWorld, const std::string& name, int material, const Resolve& resolve) {
  const std::string fn = requiredFilename(e, " (the grid's .vol file)");
  const std::string normals = e.located([&] { return e.props.getString("normals", "smooth"); });
  if (normals != "smooth" && normals != "analytic")
    e.failParam("normals", "'normals' must be 'smooth' or 'analytic', got '" + normals + "'");
  const float det = glm::determinant(Mat3(toWorld));
  if (!(std::fabs(det) > 0.0f) || !std::isfinite(det)) e.failParam("to_world", "the sdfgrid's to_world is singular");
  const std::string path = resolve(fn);
  SdfGrid g = e.located([&] { return loadSdfGrid(path); });
  g.name = name;
  g.toWorld = toWorld;
  g.toObject = glm::inverse(toWorld);
  g.smoothNormals = normals == "smooth";
  g.bsdf = material;
  return g;
}

// The object-space triangles of a mesh shape, loaded from its file or generated; sets the
// policy's face_normals where the type takes it. `resolve` turns the filename into a path.
template <class Resolve>
MeshData shapeMeshData(const Element& e, MeshPolicy& policy, const Resolve& resolve) {
  MeshData data;
  const bool fromFile = e.type == "obj" || e.type == "ply" || e.type == "serialized";
  if (fromFile || e.type == "cube")
    policy.faceNormals = e.located([&] { return e.props.getBool("face_normals", false); });
  if (fromFile) {
    const std::string path = resolve(requiredFilename(e, ""));
    if (e.type == "obj") {
      const bool flipUv = e.located([&] { return e.props.getBool("flip_tex_coords", true); });
      data = e.located([&] { return loadObj(path, flipUv); });
    } else if (e.type == "serialized") {
      const int index = e.located([&] { return e.props.getInt("shape_index", 0); });
      if (index < 0) e.failParam("shape_index", "'shape_index' must be non-negative");
      data = e.located([&] { return loadSerialized(path, index); });
    } else {
      data = e.located([&] { return loadPly(path); });
    }
  } else if (e.type == "rectangle") {
    data = makeRectangle();
  } else if (e.type == "cube") {
    data = makeCube();
  } else {
    data = makeDisk(128);
  }
  return data;
}

}  // namespace

void Loader::buildShape(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  const std::string type = node.attribute("type").value();
  if (type == "shapegroup") buildShapeGroup(file, node);
  else if (type == "instance") buildInstance(file, node);
  else buildShapeInto(file, node, scene_, nullptr);
}

void Loader::buildShapeInto(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node, ShapeLists& into,
                            const Element* group) {
  const Element e = parseElement(file, node);
  static const char* kTypes[] = {"obj", "ply", "serialized", "rectangle", "cube", "disk", "sphere", "cylinder",
                                "linearcurve", "bsplinecurve", "sdfgrid"};
  bool known = false;
  for (const char* t : kTypes) known = known || e.type == t;
  if (e.type.empty()) e.fail("missing attribute 'type'");
  if (group && (e.type == "shapegroup" || e.type == "instance"))
    e.fail("a " + e.type + " inside the shapegroup at " + group->where() + " (Mitsuba permits no nesting)");
  if (!known) {
    unsupported(e.where() + ": unknown plugin '" + e.type + "'");
    return;  // lenient: the shape is left out
  }

  // Nested material and emitter (the emitter is built once the shape has its index).
  BsdfPtr bsdf;
  MediumInterface media;
  pugi::xml_node emitterNode;
  std::shared_ptr<XmlFile> emitterFile = file;
  for (const pugi::xml_node& child : e.children) {
    const std::string tag = child.name();
    const auto* sharedEmitter = tag == "ref" ? areaEmitter(child.attribute("id").value()) : nullptr;
    const std::string role = child.attribute("name").value();
    if ((tag == "medium" || tag == "ref") && (role == "interior" || role == "exterior")) {
      int& side = role == "interior" ? media.interior : media.exterior;
      if (side >= 0) throw LocatedError(whereOf(*file, child) + ": the shape's " + role + " medium is given twice");
      side = mediumOf(file, child);
    } else if (tag == "medium") {
      throw LocatedError(whereOf(*file, child) + ": a shape's <medium> needs name=\"interior\" or name=\"exterior\"");
    } else if (sharedEmitter) {
      if (emitterNode) throw LocatedError(whereOf(*file, child) + ": a shape takes one emitter, this is the second");
      emitterFile = sharedEmitter->first;
      emitterNode = sharedEmitter->second;
      substituted(emitterFile, emitterNode);
    } else if (tag == "bsdf" || tag == "ref") {
      if (bsdf) throw LocatedError(whereOf(*file, child) + ": a shape takes one bsdf, this is the second");
      if (tag == "bsdf") {
        bsdf = buildBsdf(file, child);
      } else {
        const Named& n = resolveRef(file, child);
        if (n.kind != Kind::Bsdf || !n.bsdf)
          throw LocatedError(whereOf(*file, child) + ": id '" + std::string(child.attribute("id").value()) +
                             "' (defined at " + n.where + ") is not a bsdf");
        bsdf = n.bsdf;
      }
    } else if (tag == "emitter") {
      if (emitterNode) throw LocatedError(whereOf(*file, child) + ": a shape takes one emitter, this is the second");
      emitterNode = child;
      emitterFile = file;
    } else {
      unexpectedChild(e, child);
    }
  }
  if (group && emitterNode)
    throw LocatedError(whereOf(*emitterFile, emitterNode) + ": an emitter on a shape inside the shapegroup at " +
                       group->where() + " (Mitsuba cannot instance emitters)");
  if (!bsdf) bsdf = defaultBsdf(!emitterNode.empty());
  const int material = bsdfIndex(bsdf);
  const std::string name = (e.id.empty() ? anonymousName(e.type) : e.id) + " (" + file->location(node) + ")";

  const bool flip = e.located([&] { return e.props.getBool("flip_normals", false); });
  const Mat4 toWorld = e.transform("to_world");
  int meshIndex = -1, sphereIndex = -1;

  const bool curve = e.type == "linearcurve" || e.type == "bsplinecurve";
  if (emitterNode && (e.type == "cylinder" || e.type == "sdfgrid" || curve)) {
    // Mitsuba 3 cannot sample a position on a curve or an sdfgrid either (Shape::sample_position
    // is not implemented for them), so it cannot render one as an area light.
    unsupported(whereOf(*emitterFile, emitterNode) + ": an area emitter on a " + e.type + " is not supported");
    emitterNode = pugi::xml_node();  // lenient: the shape is kept without its emission
  }
  if (e.type == "cylinder" || e.type == "sphere" || e.type == "sdfgrid" || curve) checkMeshAttributes(e, bsdf, nullptr);
  if (media.transition() && (e.type == "cylinder" || curve))
    unsupported(e.where() + ": media on a " + e.type + " are not supported (an open surface bounds no volume)");
  if (media.transition() && e.type == "sdfgrid") unsupported(e.where() + ": media inside an sdfgrid are not supported");
  const auto resolve = [&](const std::string& fn) { return resolvePath(e, fn); };
  if (curve) {
    if (flip) e.failParam("flip_normals", "a curve's normals cannot be flipped (its inside is never hit)");
    into.curves.push_back(makeCurve(e, toWorld, name, material, resolve));
  } else if (e.type == "sdfgrid") {
    if (flip) e.failParam("flip_normals", "Mitsuba's sdfgrid has no 'flip_normals' (its normal is the distance's gradient)");
    into.sdfGrids.push_back(makeSdfGrid(e, toWorld, name, material, resolve));
  } else if (e.type == "cylinder") {
    into.cylinders.push_back(makeCylinder(e, toWorld, name, flip, material));
  } else if (e.type == "sphere") {
    sphereIndex = static_cast<int>(into.spheres.size());
    into.spheres.push_back(makeSphere(e, toWorld, name, flip, material));
    into.spheres.back().media = media;
  } else {
    MeshPolicy policy;
    policy.flipNormals = flip;
    MeshData data = shapeMeshData(e, policy, resolve);
    Mesh mesh = buildMesh(std::move(data), toWorld, policy);
    if (mesh.triangles.empty())
      unsupported(e.where() + ": the mesh has no valid triangles (" + std::to_string(mesh.degenerateSkipped) +
                  " degenerate ones dropped)");
    checkMeshAttributes(e, bsdf, &mesh);
    mesh.name = name;
    mesh.bsdf = material;
    mesh.media = media;
    meshIndex = static_cast<int>(into.meshes.size());
    into.meshes.push_back(std::move(mesh));
  }
  checkUnused(e);
  registerId(e, Kind::Shape);
  if (emitterNode) buildEmitter(emitterFile, emitterNode, meshIndex, sphereIndex);
}

}  // namespace rc
