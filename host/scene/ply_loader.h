#pragma once
// Stanford PLY reader: ascii and binary_little_endian. Element `vertex` with x y z, optional
// nx ny nz and uvs (u v | s t | texture_u texture_v | texture_s texture_t), element `face` with a
// list property vertex_indices (or vertex_index), any count/index scalar types, fan-triangulated.
// Other scalar vertex/face properties become named attributes as Mitsuba's loader groups them
// (MeshData::attributes, read by mesh_attribute textures); other elements are read past.
#include <string>

#include "scene/mesh_data.h"

namespace rc {

// Throws rc::Error("path: what") on unreadable files, malformed headers, a body shorter than the
// header promises, or face indices out of range.
MeshData loadPly(const std::string& path);

}  // namespace rc
