#pragma once
// One plugin element of a scene file (<bsdf>, <shape>, <emitter>, ...) with its properties,
// named transforms and nested elements separated, plus the helpers every builder uses to report
// problems as "file:line: <tag type=...>: what".
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "core/error.h"
#include "core/math.h"
#include "core/properties.h"
#include "scene/xml_file.h"

namespace rc {

// An rc::Error whose message already carries its file:line, so outer handlers do not prefix it again.
class LocatedError : public Error {
 public:
  using Error::Error;
};

// "file:line: <tag ...>" for a node of `file`.
std::string whereOf(const XmlFile& file, const pugi::xml_node& node);

struct Element {
  std::shared_ptr<XmlFile> file;
  pugi::xml_node node;
  std::string tag, type, id;
  Properties props;                          // typed values, with use-tracking
  std::map<std::string, std::string> raw;    // property name → value text as written (after $ substitution)
  struct Transform {
    Mat4 matrix{1.0f};
    int line = 0;
    mutable bool used = false;
  };
  std::map<std::string, Transform> transforms;  // <transform name="...">
  std::vector<pugi::xml_node> children;          // nested plugin elements and <ref>s, in order

  std::string where() const { return whereOf(*file, node); }
  int line() const { return file->lineOf(node); }
  // "file:L: <tag ...>" where L is a parameter's line (falls back to the element's line).
  std::string whereParam(const std::string& name) const;
  [[noreturn]] void fail(const std::string& message) const { throw LocatedError(where() + ": " + message); }
  [[noreturn]] void failParam(const std::string& name, const std::string& message) const {
    throw LocatedError(whereParam(name) + ": " + message);
  }
  // The named transform (marked used), or identity when absent.
  Mat4 transform(const std::string& name) const;
  bool hasTransform(const std::string& name) const { return transforms.count(name) != 0; }

  // Runs f; an unlocated rc::Error from it (a Properties getter, the BSDF factory, a mesh loader)
  // gets this element's location prefixed, a LocatedError passes through unchanged.
  template <class F>
  auto located(F&& f) const -> decltype(f()) {
    try {
      return f();
    } catch (const LocatedError&) {
      throw;
    } catch (const Error& e) {
      // Factories may already name the element ("<bsdf type="x">: ..."); do not say it twice.
      std::string msg = e.what();
      const std::string self = "<" + tag + " type=\"" + type + "\">: ";
      if (msg.compare(0, self.size(), self) == 0) msg.erase(0, self.size());
      throw LocatedError(where() + ": " + msg);
    }
  }
};

// Parses the attributes (type, id, name only), property children, transforms and nested
// elements of `node`. Duplicate names, malformed or non-finite values throw LocatedError.
Element parseElement(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node);

// True for the tags that are properties (integer float boolean string rgb spectrum point vector).
bool isPropertyTag(const std::string& tag);

}  // namespace rc
