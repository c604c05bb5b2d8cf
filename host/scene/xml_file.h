#pragma once
// One parsed XML file of a scene: the pugixml document plus what error messages need, the
// file's path as the user wrote it and a map from byte offsets (pugixml's offset_debug) to lines.
#include <memory>
#include <string>
#include <vector>

#include <pugixml.hpp>

namespace rc {

// Deepest element nesting accepted. The loader's passes (substitution, elements, nested BSDFs)
// recurse once per level; real scenes nest a dozen levels (scene, shape, twosided, blend, bsdf,
// texture), and 100k levels overflowed the stack.
constexpr int kMaxElementDepth = 128;

class XmlFile {
 public:
  // Reads and parses `path`; throws rc::Error ("path:line: XML parse error: ...") on failure.
  // `includedFrom` ("file:line") prefixes a missing-file message so the user sees who asked.
  static std::shared_ptr<XmlFile> load(const std::string& path, const std::string& includedFrom = "");

  const std::string& path() const { return path_; }
  pugi::xml_node root() const { return doc_.document_element(); }
  int lineOf(const pugi::xml_node& node) const;  // 1-based, 0 when unknown
  int lineOfOffset(ptrdiff_t offset) const;
  std::string location(const pugi::xml_node& node) const;  // "path:line"

 private:
  void checkNestingDepth() const;  // throws "path:line: elements nested deeper than ..."
  std::string path_;
  std::string text_;
  std::vector<size_t> lineStarts_;  // byte offset of the first character of each line
  pugi::xml_document doc_;
};

// "<bsdf type="foo" id="bar">" for messages: the tag with its identifying attributes.
std::string describeElement(const pugi::xml_node& node);

}  // namespace rc
