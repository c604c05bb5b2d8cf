#include "scene/obj_loader.h"

#include <fstream>
#include <sstream>
#include <unordered_map>

#include "core/error.h"
#include "core/regular_file.h"
#include "scene/value_parsing.h"

namespace rc {

namespace {

struct Corner {
  long long v = 0, vt = 0, vn = 0;  // 1-based resolved indices, 0 = absent
  bool operator==(const Corner& o) const { return v == o.v && vt == o.vt && vn == o.vn; }
};
struct CornerHash {
  size_t operator()(const Corner& c) const {
    return std::hash<long long>()(c.v) ^ (std::hash<long long>()(c.vt) * 31) ^ (std::hash<long long>()(c.vn) * 1000003);
  }
};

// Resolves one OBJ index (1-based, or negative = relative to the end) against `count` elements.
long long resolveIndex(const std::string& text, size_t count, const char* what) {
  const long long i = parseInteger(text);
  const long long n = static_cast<long long>(count);
  if (i == 0) throw Error(std::string(what) + " index 0 is invalid (OBJ indices start at 1)");
  const long long r = i > 0 ? i : n + i + 1;
  if (r < 1 || r > n)
    throw Error(std::string(what) + " index " + text + " out of range (" + std::to_string(n) + " defined so far)");
  return r;
}

// What the OBJ file declares, before corners are deduplicated into mesh vertices.
struct ObjData {
  std::vector<Vec3> v, vn;
  std::vector<Vec2> vt;
  std::vector<Corner> corners;  // three per triangle
};

// Parses one face corner "v", "v/vt", "v//vn" or "v/vt/vn" against the data declared so far.
Corner parseCorner(const std::string& a, const ObjData& d) {
  Corner c;
  const size_t s1 = a.find('/');
  const size_t s2 = s1 == std::string::npos ? std::string::npos : a.find('/', s1 + 1);
  c.v = resolveIndex(a.substr(0, s1), d.v.size(), "vertex");
  if (s1 != std::string::npos) {
    const std::string t = a.substr(s1 + 1, s2 == std::string::npos ? std::string::npos : s2 - s1 - 1);
    if (!t.empty()) c.vt = resolveIndex(t, d.vt.size(), "texture coordinate");
    if (s2 != std::string::npos) c.vn = resolveIndex(a.substr(s2 + 1), d.vn.size(), "normal");
  }
  return c;
}

// Applies one command line (already split into `cmd` and `args`); unknown commands are ignored.
void parseCommand(const std::string& cmd, const std::vector<std::string>& args, bool flipTexCoords, ObjData& d) {
  auto need = [&](size_t n) {
    if (args.size() < n)
      throw Error("'" + cmd + "' needs " + std::to_string(n) + " values, got " + std::to_string(args.size()));
  };
  // Vertex data may hold NaN/Inf in a broken file; they are kept and the triangles using them
  // are dropped (and counted) by the mesh builder, so parse with strtod semantics here.
  auto num = [&](const std::string& s) {
    char* end = nullptr;
    const double dv = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) throw Error("'" + s + "' is not a number");
    return float(dv);
  };
  if (cmd == "v") {
    need(3);
    d.v.emplace_back(num(args[0]), num(args[1]), num(args[2]));
  } else if (cmd == "vn") {
    need(3);
    d.vn.emplace_back(num(args[0]), num(args[1]), num(args[2]));
  } else if (cmd == "vt") {
    need(1);
    const float s = num(args[0]);
    const float t = args.size() > 1 ? num(args[1]) : 0.0f;
    d.vt.emplace_back(s, flipTexCoords ? 1.0f - t : t);
  } else if (cmd == "f") {
    if (args.size() < 3) throw Error("face needs at least 3 vertices, got " + std::to_string(args.size()));
    std::vector<Corner> face;
    for (const std::string& a : args) face.push_back(parseCorner(a, d));
    for (size_t k = 1; k + 1 < face.size(); ++k) {
      d.corners.push_back(face[0]);
      d.corners.push_back(face[k]);
      d.corners.push_back(face[k + 1]);
    }
  }
}

// Reads every line; errors name path:line.
ObjData parseObjFile(std::ifstream& in, const std::string& path, bool flipTexCoords) {
  ObjData d;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream ls(line);
    std::string cmd;
    if (!(ls >> cmd) || cmd[0] == '#') continue;
    try {
      std::vector<std::string> args;
      for (std::string a; ls >> a;) {
        if (a[0] == '#') break;
        args.push_back(a);
      }
      parseCommand(cmd, args, flipTexCoords, d);
    } catch (const Error& e) {
      throw Error(path + ":" + std::to_string(lineNo) + ": " + e.what());
    }
  }
  return d;
}

// One mesh vertex per distinct corner; normals and uvs only when every corner has them.
MeshData buildMesh(const ObjData& d) {
  const std::vector<Corner>& corners = d.corners;
  bool allNormals = !corners.empty(), allUvs = !corners.empty();
  for (const Corner& c : corners) {
    allNormals = allNormals && c.vn != 0;
    allUvs = allUvs && c.vt != 0;
  }
  MeshData mesh;
  std::unordered_map<Corner, uint32_t, CornerHash> index;
  std::vector<uint32_t> ids;
  ids.reserve(corners.size());
  for (Corner c : corners) {
    if (!allNormals) c.vn = 0;
    if (!allUvs) c.vt = 0;
    auto it = index.find(c);
    if (it == index.end()) {
      const uint32_t id = static_cast<uint32_t>(mesh.positions.size());
      mesh.positions.push_back(d.v[c.v - 1]);
      if (allNormals) mesh.normals.push_back(d.vn[c.vn - 1]);
      if (allUvs) mesh.uvs.push_back(d.vt[c.vt - 1]);
      it = index.emplace(c, id).first;
    }
    ids.push_back(it->second);
  }
  for (size_t i = 0; i + 2 < ids.size(); i += 3) mesh.triangles.emplace_back(ids[i], ids[i + 1], ids[i + 2]);
  return mesh;
}

}  // namespace

MeshData loadObj(const std::string& path, bool flipTexCoords) {
  requireRegularFile(path, "mesh file");
  std::ifstream in(path);
  if (!in) throw Error("cannot open mesh file '" + path + "'");
  const ObjData data = parseObjFile(in, path, flipTexCoords);
  if (in.bad()) throw Error("error reading mesh file '" + path + "'");
  return buildMesh(data);
}

}  // namespace rc
