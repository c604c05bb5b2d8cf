#pragma once
// Values a mesh file carries per vertex or per face beyond positions, normals and uvs (a PLY's
// colours and other properties), named and grouped as Mitsuba's PLY loader does
// (scene/ply_loader.h); a `mesh_attribute` texture reads them at a surface point.
#include <string>
#include <vector>

namespace rc {

struct MeshAttribute {
  std::string name;           // "vertex_color", "face_color", "vertex_<prefix>", "face_<prefix>"
  bool perFace = false;       // false: per vertex, interpolated with the hit's barycentrics
  int channels = 1;           // 1, 3, or 4 for a colour with alpha
  std::vector<float> values;  // `channels` per vertex, or per triangle (a polygon's for each of its triangles)
};

using MeshAttributes = std::vector<MeshAttribute>;

}  // namespace rc
