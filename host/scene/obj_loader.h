#pragma once
// Wavefront OBJ reader: v / vt / vn and f (3+ corners, fan-triangulated; v, v/vt, v//vn, v/vt/vn;
// negative = relative indices). Corners with equal (v, vt, vn) become one vertex. Normals or uvs
// are kept only when every corner has them. Other statements (o, g, s, usemtl, mtllib, l, p) are
// ignored: they carry no geometry we render.
#include <string>

#include "scene/mesh_data.h"

namespace rc {

// Throws rc::Error("path:line: what") on unreadable files, malformed numbers, index 0 or out of range.
// flipTexCoords: v → 1 − v (Mitsuba's `flip_tex_coords`, default true for OBJ).
MeshData loadObj(const std::string& path, bool flipTexCoords);

}  // namespace rc
