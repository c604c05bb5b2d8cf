#pragma once
// Mitsuba's `serialized` mesh format, versions 3 and 4 (the ones Mitsuba 0.6–3 writes): per shape a
// little-endian header (uint16 0x041C, uint16 version) followed by a zlib stream holding the flag
// word (0x1 normals, 0x2 uvs, 0x8 colours, 0x2000 doubles), the name (version 4, NUL-terminated),
// uint64 vertex and triangle counts, the per-vertex arrays and 3·F uint32 indices. A file may hold
// several shapes; its tail lists their offsets (uint64 in version 4, uint32 in version 3) and count.
#include <string>

#include "scene/mesh_data.h"

namespace rc {

// Shape `shapeIndex` of the file. Throws rc::Error("path: what") on unreadable or malformed files:
// wrong magic, an unknown version, an index beyond the file's shape count, counts the stream cannot
// hold, a truncated or corrupt stream, or indices out of range. Vertex colours are read past.
MeshData loadSerialized(const std::string& path, int shapeIndex);

}  // namespace rc
