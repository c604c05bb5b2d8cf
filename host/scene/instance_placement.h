#pragma once
// Mitsuba's `instance`: a copy of a shapegroup's shapes placed in the scene by the instance's
// to_world (rcache flattens instances: each copy is world-space geometry like any other shape,
// so nothing after the loader knows about groups; docs/ARCHITECTURE.md §Scene format says why).
#include <string>

#include "scene/scene.h"

namespace rc {

// Appends to `into` every shape of `group` placed by toWorld, as Mitsuba's instance transforms
// its group's hits: points by toWorld, normals by its inverse transpose (a mesh's normals were
// made in the group's space, before the placement, so a non-uniform scale bends them as Mitsuba's
// do), uv unchanged. The copies are named "<shape> in <instanceName>". Throws rc::Error for what
// a copy cannot represent: a sphere placed by a map that is not a similarity (Mitsuba renders an
// ellipsoid), a curve by a non-uniform scale (Mitsuba scales its radii with the map).
void placeInstance(const ShapeLists& group, const Mat4& toWorld, const std::string& instanceName, ShapeLists& into);

// The number of triangles, curve segments and sdfgrid voxels one placement of `group` adds: what
// the loader bounds (scene/instance_builder.cpp).
size_t instancePrimitives(const ShapeLists& group);

}  // namespace rc
