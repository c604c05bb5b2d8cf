#include "scene/ply_loader.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/regular_file.h"

namespace rc {

namespace {

enum class Scalar { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool scalarFromName(const std::string& n, Scalar& s) {
  static const std::pair<const char*, Scalar> table[] = {
      {"char", Scalar::Int8},     {"int8", Scalar::Int8},      {"uchar", Scalar::UInt8},  {"uint8", Scalar::UInt8},
      {"short", Scalar::Int16},   {"int16", Scalar::Int16},    {"ushort", Scalar::UInt16}, {"uint16", Scalar::UInt16},
      {"int", Scalar::Int32},     {"int32", Scalar::Int32},    {"uint", Scalar::UInt32},  {"uint32", Scalar::UInt32},
      {"float", Scalar::Float32}, {"float32", Scalar::Float32}, {"double", Scalar::Float64}, {"float64", Scalar::Float64}};
  for (const auto& e : table)
    if (n == e.first) {
      s = e.second;
      return true;
    }
  return false;
}

size_t scalarSize(Scalar s) {
  switch (s) {
    case Scalar::Int8: case Scalar::UInt8: return 1;
    case Scalar::Int16: case Scalar::UInt16: return 2;
    case Scalar::Int32: case Scalar::UInt32: case Scalar::Float32: return 4;
    case Scalar::Float64: return 8;
  }
  return 0;
}

bool isIntegral(Scalar s) { return s != Scalar::Float32 && s != Scalar::Float64; }

struct PlyProperty {
  std::string name;
  bool isList = false;
  Scalar countType = Scalar::UInt8, type = Scalar::Float32;
};

struct PlyElement {
  std::string name;
  size_t count = 0;
  std::vector<PlyProperty> props;
};

// Reads scalar values from the body, ascii tokens or little-endian binary.
class BodyReader {
 public:
  BodyReader(const std::string& data, size_t pos, bool binary, int firstLine)
      : data_(data), pos_(pos), binary_(binary), line_(firstLine) {}

  double read(Scalar s) {
    if (binary_) return readBinary(s);
    const std::string tok = token();
    char* end = nullptr;
    const double v = std::strtod(tok.c_str(), &end);
    if (end != tok.c_str() + tok.size()) fail("'" + tok + "' is not a number");
    if (isIntegral(s) && !(std::isfinite(v) && v == std::floor(v))) fail("'" + tok + "' is not an integer");
    return v;
  }
  [[noreturn]] void fail(const std::string& msg) const {
    throw Error(binary_ ? msg + " (at byte " + std::to_string(pos_) + ")" : "line " + std::to_string(line_) + ": " + msg);
  }
  void eof(const std::string& what) const { fail("unexpected end of file while reading " + what + " (the header promises more data)"); }
  std::string context;  // what is being read, for the end-of-file message

 private:
  std::string token() {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_]))) {
      if (data_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ >= data_.size()) eof(context);
    const size_t b = pos_;
    while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    return data_.substr(b, pos_ - b);
  }
  double readBinary(Scalar s) {
    const size_t n = scalarSize(s);
    if (pos_ + n > data_.size()) eof(context);
    unsigned char b[8];
    std::memcpy(b, data_.data() + pos_, n);  // the file is little-endian, as is every host we build for
    pos_ += n;
    switch (s) {
      case Scalar::Int8: { int8_t v; std::memcpy(&v, b, 1); return v; }
      case Scalar::UInt8: return b[0];
      case Scalar::Int16: { int16_t v; std::memcpy(&v, b, 2); return v; }
      case Scalar::UInt16: { uint16_t v; std::memcpy(&v, b, 2); return v; }
      case Scalar::Int32: { int32_t v; std::memcpy(&v, b, 4); return v; }
      case Scalar::UInt32: { uint32_t v; std::memcpy(&v, b, 4); return v; }
      case Scalar::Float32: { float v; std::memcpy(&v, b, 4); return v; }
      case Scalar::Float64: { double v; std::memcpy(&v, b, 8); return v; }
    }
    return 0.0;
  }
  const std::string& data_;
  size_t pos_;
  bool binary_;
  int line_;
};

int findProp(const PlyElement& e, std::initializer_list<const char*> names) {
  for (const char* n : names)
    for (size_t i = 0; i < e.props.size(); ++i)
      if (e.props[i].name == n && !e.props[i].isList) return static_cast<int>(i);
  return -1;
}

// Parses the rest of a "property" header line: a scalar type and name, or "list" count and item types.
PlyProperty parsePropertyLine(std::istringstream& ls, const std::string& where) {
  PlyProperty p;
  std::string t;
  ls >> t;
  if (t == "list") {
    std::string ct, it;
    ls >> ct >> it >> p.name;
    p.isList = true;
    if (!scalarFromName(ct, p.countType) || !scalarFromName(it, p.type) || !isIntegral(p.countType))
      throw Error(where + "malformed list property");
  } else {
    if (!scalarFromName(t, p.type)) throw Error(where + "unknown property type '" + t + "'");
    ls >> p.name;
  }
  if (p.name.empty()) throw Error(where + "property without a name");
  return p;
}

// The header's declarations and where the body starts.
struct PlyHeader {
  std::vector<PlyElement> elements;
  bool binary = false;
  size_t bodyPos = 0;
  int lineCount = 0;  // header lines, so body line numbers continue from it
};

// Reads the header lines up to "end_header"; errors name path:line.
PlyHeader parseHeader(const std::string& path, const std::string& data) {
  PlyHeader h;
  size_t& pos = h.bodyPos;
  int& lineNo = h.lineCount;
  std::vector<PlyElement>& elements = h.elements;
  bool sawFormat = false, sawEnd = false;
  while (pos < data.size() && !sawEnd) {
    size_t eol = data.find('\n', pos);
    if (eol == std::string::npos) eol = data.size();
    std::string line = data.substr(pos, eol - pos);
    pos = eol + 1;
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream ls(line);
    std::string kw;
    ls >> kw;
    const std::string where = path + ":" + std::to_string(lineNo) + ": ";
    if (lineNo == 1) {
      if (kw != "ply") throw Error(where + "not a PLY file (first line must be 'ply')");
      continue;
    }
    if (kw.empty() || kw == "comment" || kw == "obj_info") continue;
    if (kw == "format") {
      std::string fmt;
      ls >> fmt;
      if (fmt == "ascii") h.binary = false;
      else if (fmt == "binary_little_endian") h.binary = true;
      else throw Error(where + "unsupported PLY format '" + fmt + "' (ascii and binary_little_endian are supported)");
      sawFormat = true;
    } else if (kw == "element") {
      PlyElement e;
      long long count = -1;
      if (!(ls >> e.name >> count) || count < 0) throw Error(where + "malformed element line");
      // A second vertex/face element would append vertices without the first one's normals/uvs
      // (arrays of different lengths) or mix index bases; no writer produces one.
      for (const PlyElement& prev : elements)
        if (prev.name == e.name && (e.name == "vertex" || e.name == "face"))
          throw Error(where + "element '" + e.name + "' is declared twice");
      e.count = static_cast<size_t>(count);
      elements.push_back(e);
    } else if (kw == "property") {
      if (elements.empty()) throw Error(where + "property before any element");
      elements.back().props.push_back(parsePropertyLine(ls, where));
    } else if (kw == "end_header") {
      sawEnd = true;
    } else {
      throw Error(where + "unknown header keyword '" + kw + "'");
    }
  }
  if (!sawEnd) throw Error(path + ": " + "header has no 'end_header'");
  if (!sawFormat) throw Error(path + ": " + "header has no 'format' line");
  return h;
}

// Which property index holds each vertex attribute or the face's index list (-1: absent).
struct PropertySlots {
  int x = -1, y = -1, z = -1, nx = -1, ny = -1, nz = -1, u = -1, v = -1, indexList = -1;
  bool hasNormals() const { return nx >= 0 && ny >= 0 && nz >= 0; }
  bool hasUvs() const { return u >= 0 && v >= 0; }
};

PropertySlots findSlots(const PlyElement& e, bool isVertex, bool isFace) {
  PropertySlots s;
  if (isVertex) {
    s.x = findProp(e, {"x"}), s.y = findProp(e, {"y"}), s.z = findProp(e, {"z"});
    if (s.x < 0 || s.y < 0 || s.z < 0) throw Error("element 'vertex' lacks x, y or z");
    s.nx = findProp(e, {"nx"}), s.ny = findProp(e, {"ny"}), s.nz = findProp(e, {"nz"});
    s.u = findProp(e, {"u", "s", "texture_u", "texture_s"});
    s.v = findProp(e, {"v", "t", "texture_v", "texture_t"});
  }
  if (isFace) {
    for (size_t i = 0; i < e.props.size(); ++i)
      if (e.props[i].isList && (e.props[i].name == "vertex_indices" || e.props[i].name == "vertex_index"))
        s.indexList = static_cast<int>(i);
    if (s.indexList < 0) throw Error("element 'face' lacks a 'vertex_indices' list");
  }
  return s;
}

// A vertex or face attribute: its name and the properties holding its channels, in order.
struct AttributeSlots {
  std::string name;
  std::vector<int> props;
};

// Mitsuba's grouping of an element's other scalar properties into attributes (src/shapes/ply.h,
// find_other_fields): r g b [a] or red green blue [alpha] anywhere make "<type>color"; then, in
// declaration order, consecutive properties "<prefix>_<c>" whose postfixes run x y z w, r g b a,
// 0 1 2 3 or 1 2 3 4 make "<type><prefix>" ("<type><prefix>_color" for r g b), kept when they
// have 1 or 3 channels. Names without a one-letter postfix and repeated prefixes are skipped.
std::vector<AttributeSlots> findAttributes(const PlyElement& e, const std::string& type, std::set<std::string> reserved) {
  std::vector<AttributeSlots> out;
  auto scalar = [&](const std::string& n) { return findProp(e, {n.c_str()}); };
  for (const auto& names : {std::vector<std::string>{"r", "g", "b", "a"}, std::vector<std::string>{"red", "green", "blue", "alpha"}}) {
    if (scalar(names[0]) < 0 || scalar(names[1]) < 0 || scalar(names[2]) < 0) continue;
    AttributeSlots color{type + "color", {scalar(names[0]), scalar(names[1]), scalar(names[2])}};
    if (scalar(names[3]) >= 0) color.props.push_back(scalar(names[3]));
    out.push_back(color);
    reserved.insert(names.begin(), names.end());
    break;
  }
  static const char* kPostfixes[4] = {"xr01", "yg12", "zb23", "wa34"};  // [channel][scheme]
  std::set<std::string> seen;
  AttributeSlots current;
  std::string prefix;
  int scheme = -1;
  auto flush = [&] {
    if (scheme >= 0 && (current.props.size() == 1 || current.props.size() == 3)) {
      current.name = type + prefix + (scheme == 1 ? "_color" : "");
      out.push_back(current);
      seen.insert(prefix);
    }
    current = AttributeSlots();
    scheme = -1;
  };
  // Skips the properties from i on that start with p (Mitsuba's recovery from a bad sequence).
  auto skipPrefix = [&](size_t& i, const std::string& p) {
    while (i + 1 < e.props.size() && e.props[i + 1].name.rfind(p, 0) == 0) ++i;
  };
  for (size_t i = 0; i < e.props.size(); ++i) {
    const PlyProperty& prop = e.props[i];
    if (prop.isList || reserved.count(prop.name)) continue;
    const size_t us = prop.name.find_last_of('_');
    if (us == std::string::npos || prop.name.size() - us != 2) {  // no postfix, or a longer one
      flush();
      continue;
    }
    const std::string p = prop.name.substr(0, us);
    const char c = prop.name[us + 1];
    if (scheme >= 0 && p != prefix) flush();
    if (scheme < 0) {
      if (seen.count(p)) {
        skipPrefix(i, p);
        continue;
      }
      const char* at = std::strchr(kPostfixes[0], c);
      if (!at || c == '\0') continue;
      scheme = static_cast<int>(at - kPostfixes[0]);
      prefix = p;
    } else if (current.props.size() >= 4 || kPostfixes[current.props.size()][scheme] != c) {
      current = AttributeSlots();
      scheme = -1;
      skipPrefix(i, p);
      continue;
    }
    current.props.push_back(static_cast<int>(i));
  }
  flush();
  return out;
}

// Reads one list property; the entries of the face's index list go to `face`, checked against
// the vertices read so far.
void readList(BodyReader& body, const PlyProperty& prop, bool isIndexList, size_t fileSize, size_t faceNo,
              size_t vertexCount, std::vector<uint32_t>& face) {
  const double n = body.read(prop.countType);
  // Each item takes at least one byte, so a length beyond the file is a lie (and one beyond
  // size_t's range would make the conversion below undefined).
  if (n < 0) body.fail("negative list length");
  if (n > double(fileSize)) body.fail("list length exceeds the file size");
  for (size_t j = 0; j < static_cast<size_t>(n); ++j) {
    const double idx = body.read(prop.type);
    if (isIndexList) {
      if (!(idx >= 0 && idx < double(vertexCount)))
        body.fail("face " + std::to_string(faceNo) + ": vertex index " + std::to_string(static_cast<long long>(idx)) +
                  " out of range (" + std::to_string(vertexCount) + " vertices)");
      face.push_back(static_cast<uint32_t>(idx));
    }
  }
}

// Reads every item of one element, appending vertices or fan-triangulated faces to the mesh.
void readElement(BodyReader& body, const PlyElement& e, size_t fileSize, MeshData& mesh) {
  body.context = "element '" + e.name + "'";
  const bool isVertex = e.name == "vertex", isFace = e.name == "face";
  const PropertySlots s = findSlots(e, isVertex, isFace);
  const bool hasN = s.hasNormals(), hasUv = s.hasUvs();
  if (e.props.empty()) return;  // nothing to read, however large the count (no empty loop of 2^63)
  std::set<std::string> reserved;
  for (int slot : {s.x, s.y, s.z, s.nx, s.ny, s.nz, s.u, s.v})
    if (slot >= 0) reserved.insert(e.props[static_cast<size_t>(slot)].name);
  const std::vector<AttributeSlots> slots =
      isVertex || isFace ? findAttributes(e, isVertex ? "vertex_" : "face_", reserved) : std::vector<AttributeSlots>();
  const size_t firstAttribute = mesh.attributes.size();
  for (const AttributeSlots& a : slots) {
    MeshAttribute attribute;
    attribute.name = a.name;
    attribute.perFace = isFace;
    attribute.channels = static_cast<int>(a.props.size());
    mesh.attributes.push_back(std::move(attribute));
  }
  std::vector<double> vals(e.props.size());
  for (size_t k = 0; k < e.count; ++k) {
    std::vector<uint32_t> face;
    for (size_t p = 0; p < e.props.size(); ++p) {
      const PlyProperty& prop = e.props[p];
      if (!prop.isList) {
        vals[p] = body.read(prop.type);
        continue;
      }
      readList(body, prop, static_cast<int>(p) == s.indexList, fileSize, k, mesh.positions.size(), face);
    }
    if (isVertex) {
      mesh.positions.emplace_back(float(vals[s.x]), float(vals[s.y]), float(vals[s.z]));
      if (hasN) mesh.normals.emplace_back(float(vals[s.nx]), float(vals[s.ny]), float(vals[s.nz]));
      if (hasUv) mesh.uvs.emplace_back(float(vals[s.u]), float(vals[s.v]));
    }
    if (isFace) {
      if (face.size() < 3) body.fail("face " + std::to_string(k) + " has fewer than 3 vertices");
      for (size_t j = 1; j + 1 < face.size(); ++j) mesh.triangles.emplace_back(face[0], face[j], face[j + 1]);
    }
    // A face's values go to each of its triangles.
    const size_t copies = isFace ? face.size() - 2 : 1;
    for (size_t a = 0; a < slots.size(); ++a)
      for (size_t copy = 0; copy < copies; ++copy)
        for (int p : slots[a].props) mesh.attributes[firstAttribute + a].values.push_back(float(vals[static_cast<size_t>(p)]));
  }
}

}  // namespace

MeshData loadPly(const std::string& path) {
  const std::string data = readRegularFile(path, "mesh file");
  auto fail = [&](const std::string& msg) -> Error { return Error(path + ": " + msg); };

  const PlyHeader header = parseHeader(path, data);
  MeshData mesh;
  BodyReader body(data, header.bodyPos, header.binary, header.lineCount + 1);
  bool sawVertex = false;
  try {
    for (const PlyElement& e : header.elements) {
      if (e.name == "vertex") sawVertex = true;
      readElement(body, e, data.size(), mesh);
    }
  } catch (const Error& e) {
    throw fail(e.what());
  }
  if (!sawVertex) throw fail("no 'vertex' element");
  return mesh;
}

}  // namespace rc
