#pragma once
// The in-memory scene after parsing (ARCHITECTURE.md §Scene format): everything in world space, ready for the BVH.
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "bsdf/bsdf.h"
#include "core/math.h"
#include "core/properties.h"
#include "scene/curve_loader.h"
#include "scene/medium.h"
#include "texture/texture.h"

namespace rc {

// A triangle mesh in world space (shapes obj/ply/rectangle/cube/disk are all turned into meshes).
struct Mesh {
  std::string name;                    // id or "<type>#<n>", and the source file:line for messages
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;           // per vertex, empty → face normals (flat shading)
  std::vector<Vec2> uvs;               // per vertex, may be empty
  std::vector<glm::uvec3> triangles;   // degenerate (zero-area) triangles removed at load
  MeshAttributes attributes;           // a PLY file's extra vertex/face values (face ones per triangle)
  int bsdf = -1;                       // index into Scene::bsdfs
  int emitter = -1;                    // index into Scene::emitters (area emitter), or -1
  MediumInterface media;               // interior/exterior media (render/volpath.h)
  size_t degenerateSkipped = 0;        // zero-area / NaN triangles dropped while loading
};

// An analytic sphere (shape `sphere`), intersected exactly.
struct Sphere {
  std::string name;
  Vec3 center{0.0f};
  float radius = 1.0f;
  bool flipNormals = false;            // normals point inward
  int bsdf = -1;
  int emitter = -1;
  MediumInterface media;
};

// An analytic open cylinder (shape `cylinder`, no caps): the unit cylinder x² + y² = 1, 0 ≤ z ≤ 1
// taken to world space by toWorld (Mitsuba's p0, p1, radius folded in; geometry/cylinder_geometry.h).
struct Cylinder {
  std::string name;
  Mat4 toWorld{1.0f};
  Mat4 toObject{1.0f};                 // inverse of toWorld
  bool flipNormals = false;            // normals point toward the axis
  int bsdf = -1;
};

// Mitsuba's `linearcurve` / `bsplinecurve`: round tubes along control points with radii
// (scene/curve_loader.h), intersected by Embree's round curves (geometry/curve_geometry.h).
struct Curve {
  std::string name;
  CurveBasis basis = CurveBasis::Linear;
  std::vector<Vec4> points;        // world-space position (to_world applied) and radius (never transformed)
  std::vector<uint32_t> segments;  // each segment's first control point
  int bsdf = -1;
};

// Mitsuba's `sdfgrid`: a signed distance sampled on a grid over the unit cube [0,1]³ of its
// object space, sample (i, j, k) at (i/(nx−1), j/(ny−1), k/(nz−1)) (the corners of the voxels),
// trilinearly interpolated; the surface is the interpolant's zero level set, hit only in the voxels
// whose corner values change sign (geometry/sdf_grid_math.h). No uv, no area emitter (Mitsuba's
// limitations too).
struct SdfGrid {
  std::string name;
  uint32_t res[3] = {2, 2, 2};      // samples along x, y, z (each ≥ 2)
  // Shared by the copies instances place (scene/instance_placement.h), which differ only in toWorld.
  std::shared_ptr<const std::vector<float>> values;     // ((z·ny + y)·nx + x), the .vol file's order
  std::shared_ptr<const std::vector<uint32_t>> voxels;  // the occupied voxels, x + (nx−1)·(y + (ny−1)·z)
  Mat4 toWorld{1.0f};
  Mat4 toObject{1.0f};              // inverse of toWorld
  bool smoothNormals = true;        // `normals`: smooth (Hansson-Söderlund et al.) or analytic
  int bsdf = -1;
  float at(uint32_t x, uint32_t y, uint32_t z) const { return (*values)[(static_cast<size_t>(z) * res[1] + y) * res[0] + x]; }
};

// The shapes of a scene, or of a `shapegroup` (in the group's own space until an instance places
// copies of them in the scene, scene/instance_placement.h).
struct ShapeLists {
  std::vector<Mesh> meshes;
  std::vector<Sphere> spheres;
  std::vector<Cylinder> cylinders;
  std::vector<Curve> curves;
  std::vector<SdfGrid> sdfGrids;
};

enum class EmitterType { Area, Point, Directional, Constant, Envmap, Spot, Projector };

struct Emitter {
  EmitterType type = EmitterType::Area;
  Color radiance{1.0f};       // area, constant
  Color intensity{1.0f};      // point, spot (W/sr; spot: on its axis)
  Color irradiance{1.0f};     // directional; projector (constant, on its image plane at z = 1)
  Vec3 position{0.0f};        // point, spot, projector
  // spot (render/spot_light.h): angles in radians from the local +z, and the inverse of
  // to_world's linear part that takes world directions into that frame (also the projector's)
  float spotCutoffRad = 0.0f, spotBeamRad = 0.0f, spotCosCutoff = 1.0f, spotCosBeam = 1.0f;
  Mat3 spotWorldToLocal{1.0f};
  // A projected image: the spot's `texture` (looked up by direction, spanning tan(cutoff) on the
  // z = 1 plane) or the projector's `irradiance` texture; null: none / the constant `irradiance`.
  TexturePtr projection;
  // projector (render/spot_light.h): cot(x_fov / 2) and the image's width / height; its `scale`
  // is `scale` below
  float projectorCot = 1.0f, projectorAspect = 1.0f;
  Vec3 direction{0, 0, 1};    // directional: direction light travels (world, unit)
  // envmap: lat-long image, Mitsuba convention (Y up in the emitter's local frame)
  std::string filename;
  float scale = 1.0f;
  Mat4 toWorld{1.0f};
  int envWidth = 0, envHeight = 0;
  std::vector<Color> envPixels;  // row-major, top row first
  // area: which shape carries it
  int mesh = -1, sphere = -1;
};

struct Camera {
  Mat4 toWorld{1.0f};          // camera looks down local +z, up is local +y, Mitsuba convention
  // Defaults of a camera built in code; a <sensor> without `fov` gets Mitsuba's 50 mm lens from
  // the loader instead (46.79° on the image diagonal).
  float fovDegrees = 39.3077f; // along fovAxis
  std::string fovAxis = "x";   // x, y, diagonal, smaller, larger
  Vec2 principalPointOffset{0.0f};   // added to the film position, in fractions of the film size
  float nearClip = 1e-2f, farClip = 1e4f;
};

struct FilmSettings {
  int width = 768, height = 576;    // the full sensor
  std::string filter = "gaussian";  // box | tent | gaussian
  float gaussianStddev = 0.5f;
  float tentRadius = 1.0f;
  // Crop window (Mitsuba's hdrfilm crop_offset_x/y, crop_width/height): only this window of the
  // sensor is rendered and the image has its size. cropWidth/Height 0 = the whole sensor.
  int cropX = 0, cropY = 0, cropWidth = 0, cropHeight = 0;
  int imageWidth() const { return cropWidth > 0 ? cropWidth : width; }
  int imageHeight() const { return cropHeight > 0 ? cropHeight : height; }
};

// Integrator block; `params` keeps every parameter of <integrator> (and -D overrides are already
// substituted) so the rcache integrator can read its own (a, rays, order, ...).
struct IntegratorSettings {
  std::string type = "path";
  // The path-tracing parameters every integrator shares (Mitsuba's max_depth, rr_depth,
  // hide_emitters), filled by readPathParams (scene/integrator_params.h) when the integrator is made.
  int maxDepth = -1;      // -1 = unbounded (Russian roulette ends paths)
  int rrDepth = 5;
  bool hideEmitters = false;
  int emitterSamples = 1, bsdfSamples = 1;  // Mitsuba's `direct`: samples of each technique per pixel sample
  Properties props;       // every parameter as written (typed, use-tracked); -D overrides as text
  std::string where;      // "file:L: <integrator ...>" for messages ("" when built in code)
  std::map<std::string, std::string> paramWhere;  // parameter → its location, for messages
  std::vector<std::string> wrappers;  // outer integrators holding this one (aov, moment), outermost first
};

// A sensor's <sampler>: its plugin, sample count and seed (a top-level <sampler id> holds the same).
struct SamplerSettings {
  // "independent" (PCG per sample) or "ldsampler" (padded Owen-scrambled Sobol,
  // core/low_discrepancy.h); Mitsuba's stratified/multijitter/orthogonal load as "ldsampler".
  std::string type = "independent";
  int sampleCount = 4;
  uint64_t seed = 0;
};

struct Scene : ShapeLists {
  std::string sourceFile;
  std::vector<BsdfPtr> bsdfs;
  std::vector<Emitter> emitters;
  std::vector<Medium> media;  // participating media (scene/medium.h), referred to by index
  int cameraMedium = -1;      // the sensor's medium (Mitsuba's sensor `medium`), −1 for none
  Camera camera;
  FilmSettings film;
  SamplerSettings sampler;
  IntegratorSettings integrator;
  // Mitsuba's scene property embree_use_robust_intersections (default false): Embree's robust mode,
  // watertight triangle tests and conservative box tests, at a cost in traversal (bench/RESULTS.md,
  // twelfth session, trace16).
  bool embreeRobust = false;
  // The names the file (with its includes) declares with <default name="...">: scene parameters
  // ($name) a -D define substitutes, whatever else the name means.
  std::set<std::string> defaultNames;
};

}  // namespace rc
