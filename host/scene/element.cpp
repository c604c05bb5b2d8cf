#include "scene/element.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "scene/spectrum_rgb.h"
#include "scene/transform_parser.h"
#include "scene/value_parsing.h"

namespace rc {

std::string whereOf(const XmlFile& file, const pugi::xml_node& node) {
  return file.location(node) + ": " + describeElement(node);
}

std::string Element::whereParam(const std::string& name) const {
  int l = props.lineOf(name);
  if (l <= 0) {
    auto it = transforms.find(name);
    if (it != transforms.end()) l = it->second.line;
  }
  if (l <= 0) l = line();
  return atLocation(file->path(), l, describeElement(node));
}

Mat4 Element::transform(const std::string& name) const {
  auto it = transforms.find(name);
  if (it == transforms.end()) return Mat4(1.0f);
  it->second.used = true;
  return it->second.matrix;
}

bool isPropertyTag(const std::string& tag) {
  return tag == "integer" || tag == "float" || tag == "boolean" || tag == "string" || tag == "rgb" ||
         tag == "spectrum" || tag == "point" || tag == "vector";
}

namespace {

// Values are stored as 32-bit floats: a finite double beyond ±3.4e38 would silently become Inf.
float toFloat(double v) {
  const float f = static_cast<float>(v);
  if (!std::isfinite(f)) {
    char text[32];
    std::snprintf(text, sizeof(text), "%g", v);
    throw Error(std::string(text) + " is out of range for a 32-bit float");
  }
  return f;
}

Vec3 toVec3(const std::vector<double>& v) { return Vec3(toFloat(v[0]), toFloat(v[1]), toFloat(v[2])); }

// Rejects any attribute of `node` not in `names`.
void allowAttributes(const pugi::xml_node& node, std::initializer_list<const char*> names) {
  for (const pugi::xml_attribute& a : node.attributes()) {
    bool ok = false;
    for (const char* n : names) ok = ok || std::string(a.name()) == n;
    if (!ok) throw Error(std::string("unsupported attribute '") + a.name() + "'");
  }
}

// <point>/<vector>: either value="x, y, z" or separate x/y/z attributes (missing ones are 0).
void parseVectorProperty(const pugi::xml_node& node, const std::string& tag, Property& p, std::string& raw) {
  const pugi::xml_attribute value = node.attribute("value");
  allowAttributes(node, {"name", "value", "x", "y", "z"});
  p.type = tag == "point" ? Property::Type::Point : Property::Type::Vector;
  if (value) {
    if (node.attribute("x") || node.attribute("y") || node.attribute("z"))
      throw Error("give either 'value' or x/y/z, not both");
    const std::vector<double> v = parseNumberList(value.value());
    if (v.size() != 3) throw Error("needs 3 numbers, got " + std::to_string(v.size()));
    p.vec = toVec3(v);
    raw = value.value();
  } else {
    auto comp = [&](const char* n) {
      const pugi::xml_attribute a = node.attribute(n);
      return a ? toFloat(parseNumber(a.value())) : 0.0f;
    };
    p.vec = Vec3(comp("x"), comp("y"), comp("z"));
    raw = std::to_string(p.vec.x) + ", " + std::to_string(p.vec.y) + ", " + std::to_string(p.vec.z);
  }
}

// <spectrum>. As Mitsuba's RGB variants (spectrum_rgb.h): wavelength:value pairs are projected to
// sRGB (reflectances bounded and under D65, emitters neither, η/k unbounded); a single value is
// grey, except on an emitter, where Mitsuba gives it the sRGB colour of a flat spectrum.
void parseSpectrumProperty(const pugi::xml_node& node, const std::string& raw, bool emitter, Property& p) {
  p.type = Property::Type::Rgb;
  if (raw.find(':') == std::string::npos) {
    const std::vector<double> v = parseNumberList(raw);
    if (v.size() != 1) throw Error("a spectrum is one value or wavelength:value pairs");
    p.vec = emitter ? uniformEmitterSpectrumRgb(toFloat(v[0])) : Vec3(toFloat(v[0]));
    return;
  }
  std::vector<double> wavelengths, values;
  std::string pairs = raw;
  for (char& c : pairs)
    if (c == ',') c = ' ';
  std::istringstream in(pairs);
  for (std::string token; in >> token;) {
    const size_t colon = token.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == token.size())
      throw Error("spectrum entry '" + token + "' is not wavelength:value");
    wavelengths.push_back(parseNumber(token.substr(0, colon)));
    values.push_back(parseNumber(token.substr(colon + 1)));
  }
  const std::string name = node.attribute("name").value();
  const bool unbounded = name == "eta" || name == "k";
  p.vec = spectrumToRgb(wavelengths, values, !(emitter || unbounded), !emitter);
}

// Parses one property element into `p` (and its text form into `raw`).
void parseProperty(const pugi::xml_node& node, const std::string& tag, bool emitter, Property& p, std::string& raw) {
  if (tag == "point" || tag == "vector") {
    parseVectorProperty(node, tag, p, raw);
    return;
  }
  const pugi::xml_attribute value = node.attribute("value");
  allowAttributes(node, {"name", "value"});
  if (!value) throw Error("missing attribute 'value'");
  raw = value.value();
  if (tag == "integer") {
    p.type = Property::Type::Integer;
    p.number = double(parseInteger(raw));
  } else if (tag == "float") {
    p.type = Property::Type::Float;
    p.number = parseNumber(raw);
    toFloat(p.number);
  } else if (tag == "boolean") {
    p.type = Property::Type::Boolean;
    p.boolean = parseBoolean(raw);
  } else if (tag == "string") {
    p.type = Property::Type::String;
    p.text = raw;
  } else if (tag == "rgb") {
    p.type = Property::Type::Rgb;
    const std::vector<double> v = parseNumberList(raw);
    if (v.size() == 1) p.vec = Vec3(toFloat(v[0]));
    else if (v.size() == 3) p.vec = toVec3(v);
    else throw Error("rgb needs 1 or 3 numbers, got " + std::to_string(v.size()));
  } else if (tag == "spectrum") {
    parseSpectrumProperty(node, raw, emitter, p);
  }
}

}  // namespace

Element parseElement(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  Element e;
  e.file = file;
  e.node = node;
  e.tag = node.name();
  e.type = node.attribute("type").value();
  e.id = node.attribute("id").value();
  for (const pugi::xml_attribute& a : node.attributes()) {
    const std::string n = a.name();
    if (n != "type" && n != "id" && n != "name") e.fail("unsupported attribute '" + n + "'");
  }
  if (node.attribute("id") && e.id.empty()) e.fail("empty 'id'");
  e.props.pluginType = e.type;
  e.props.location = file->location(node);

  for (const pugi::xml_node& child : node.children()) {
    if (child.type() != pugi::node_element) continue;
    const std::string tag = child.name();
    const std::string name = child.attribute("name").value();
    const bool isProp = isPropertyTag(tag);
    if (isProp || tag == "transform") {
      if (name.empty()) throw LocatedError(whereOf(*file, child) + ": missing attribute 'name'");
      if (e.props.has(name) || e.transforms.count(name))
        throw LocatedError(whereOf(*file, child) + ": parameter '" + name + "' is given more than once");
    }
    if (isProp) {
      Property p;
      p.line = file->lineOf(child);
      std::string raw;
      try {
        parseProperty(child, tag, e.tag == "emitter", p, raw);
      } catch (const LocatedError&) {
        throw;
      } catch (const Error& err) {
        throw LocatedError(whereOf(*file, child) + ": " + err.what());
      }
      e.props.set(name, p);
      e.raw[name] = raw;
    } else if (tag == "transform") {
      for (const pugi::xml_attribute& a : child.attributes())
        if (std::string(a.name()) != "name")
          throw LocatedError(whereOf(*file, child) + ": unsupported attribute '" + a.name() + "'");
      Element::Transform t;
      t.line = file->lineOf(child);
      try {
        t.matrix = parseTransform(child, [&](const pugi::xml_node& n) { return whereOf(*file, n); });
      } catch (const LocatedError&) {
        throw;
      } catch (const Error& err) {
        throw LocatedError(err.what());  // parseTransform's messages carry their location already
      }
      e.transforms[name] = t;
    } else {
      e.children.push_back(child);
    }
  }
  return e;
}

}  // namespace rc
