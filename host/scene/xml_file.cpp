#include "scene/xml_file.h"

#include <algorithm>

#include "core/error.h"
#include "core/regular_file.h"

namespace rc {

std::shared_ptr<XmlFile> XmlFile::load(const std::string& path, const std::string& includedFrom) {
  auto file = std::make_shared<XmlFile>();
  file->path_ = path;
  try {
    file->text_ = readRegularFile(path, "scene file");
  } catch (const Error& e) {
    throw Error(includedFrom.empty() ? std::string(e.what()) : includedFrom + ": " + e.what());
  }
  file->lineStarts_.push_back(0);
  for (size_t i = 0; i < file->text_.size(); ++i)
    if (file->text_[i] == '\n') file->lineStarts_.push_back(i + 1);

  // parse_default keeps offsets for offset_debug(); the buffer is UTF-8 so offsets are bytes
  // into text_, which is what lineStarts_ indexes.
  const pugi::xml_parse_result result =
      file->doc_.load_buffer(file->text_.data(), file->text_.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!result)
    throw Error(atLocation(path, file->lineOfOffset(result.offset), std::string("XML parse error: ") + result.description()));
  if (!file->doc_.document_element())
    throw Error(atLocation(path, 0, "XML parse error: no root element"));
  file->checkNestingDepth();
  return file;
}

void XmlFile::checkNestingDepth() const {
  // Iterative walk (first child, next sibling, parent): the check itself must not recurse.
  pugi::xml_node node = doc_.document_element();
  int depth = 1;
  while (node) {
    if (depth > kMaxElementDepth)
      throw Error(location(node) + ": elements nested deeper than " + std::to_string(kMaxElementDepth) + " levels");
    if (pugi::xml_node child = node.first_child()) {
      node = child;
      ++depth;
      continue;
    }
    while (node && !node.next_sibling()) {
      node = node.parent();
      --depth;
    }
    if (node) node = node.next_sibling();
  }
}

int XmlFile::lineOfOffset(ptrdiff_t offset) const {
  if (offset < 0) return 0;
  auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), static_cast<size_t>(offset));
  return static_cast<int>(it - lineStarts_.begin());
}

int XmlFile::lineOf(const pugi::xml_node& node) const { return lineOfOffset(node.offset_debug()); }

std::string XmlFile::location(const pugi::xml_node& node) const {
  const int line = lineOf(node);
  return line > 0 ? path_ + ":" + std::to_string(line) : path_;
}

std::string describeElement(const pugi::xml_node& node) {
  std::string s = std::string("<") + node.name();
  for (const char* key : {"type", "name", "id"}) {
    const pugi::xml_attribute a = node.attribute(key);
    if (a) s += std::string(" ") + key + "=\"" + a.value() + "\"";
  }
  return s + ">";
}

}  // namespace rc
