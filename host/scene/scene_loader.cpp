// loadScene(): walks the scene file(s) in document order — <default>/$name substitution,
// <include>, ids and refs — and hands each plugin element to its builder.
#include "scene/scene_loader.h"

#include <algorithm>
#include <filesystem>
#include <regex>

#include "core/regular_file.h"
#include "scene/loader.h"
#include "scene/value_parsing.h"

namespace rc {

namespace fs = std::filesystem;

namespace {
// Each <include> level recurses through processFile; a file that includes the next one twice
// doubles the work per level (2^30 reads for 30 files), so both the depth and the total count of
// includes are bounded, far above what scenes split into parts use.
constexpr size_t kMaxIncludeDepth = 64;
constexpr size_t kMaxIncludes = 10000;
}  // namespace

Scene loadScene(const std::string& path, const LoadOptions& options, std::vector<std::string>* warnings) {
  Loader loader(options, warnings);
  return loader.load(path);
}

Loader::Loader(const LoadOptions& options, std::vector<std::string>* warnings)
    : options_(options), warnings_(warnings), params_(options.defines) {}

Scene Loader::load(const std::string& path) {
  scene_ = Scene();
  scene_.sourceFile = path;
  mainDir_ = fs::path(path).parent_path().string();
  auto file = XmlFile::load(path);
  includeStack_ = {fs::weakly_canonical(path).string()};
  processFile(file, "");
  if (sensors_ == 0)
    throw Error(whereOf(*file, file->root()) + ": the scene has no <sensor> (rcache, like Mitsuba 3, needs a camera)");
  return std::move(scene_);
}

void Loader::processFile(const std::shared_ptr<XmlFile>& file, const std::string& includedFrom) {
  files_.push_back(file);
  const pugi::xml_node root = file->root();
  const std::string prefix = includedFrom.empty() ? "" : " (included from " + includedFrom + ")";
  if (std::string(root.name()) != "scene")
    throw Error(whereOf(*file, root) + ": the root element must be <scene>" + prefix);
  const pugi::xml_attribute version = root.attribute("version");
  if (!version) throw Error(whereOf(*file, root) + ": missing attribute 'version' (e.g. version=\"3.0.0\")");
  static const std::regex versionFormat(R"((\d+)\.(\d+)\.(\d+))");
  std::smatch m;
  const std::string v = version.value();
  if (!std::regex_match(v, m, versionFormat))
    throw Error(whereOf(*file, root) + ": malformed version '" + v + "' (expected major.minor.patch)");
  // Version 0.x/1.x files use Mitsuba 0.6 parameter names that Mitsuba 3 upgrades on load; we do not.
  // (compared as text: std::stoi would throw std::out_of_range on a huge major number)
  const std::string major = m[1].str().substr(std::min(m[1].str().find_first_not_of('0'), m[1].str().size() - 1));
  if (major.size() == 1 && major[0] < '2')
    throw Error(whereOf(*file, root) + ": scene version " + v + " (Mitsuba 0.6 syntax) is not supported; use 3.0.0");
  for (const pugi::xml_attribute& a : root.attributes())
    if (std::string(a.name()) != "version")
      throw Error(whereOf(*file, root) + ": unsupported attribute '" + a.name() + "'");

  // Mitsuba substitutes in document order, one element after the other, with one parameter list
  // for the whole load: a <default> applies to what follows it, also to the includer's elements
  // after an <include> whose file defines it, and never to what came before.
  for (const pugi::xml_node& child : root.children("emitter"))
    if (std::string(child.attribute("type").value()) == "area" && child.attribute("id"))
      areaEmitters_.emplace(areaEmitterId(child), std::make_pair(file, child));
  for (pugi::xml_node child : root.children()) {
    if (child.type() != pugi::node_element) continue;
    substituted(file, child);
    sceneChild(file, child);
  }
}

std::string Loader::areaEmitterId(const pugi::xml_node& node) const {
  // Shapes may <ref> an area emitter defined after them (Mitsuba resolves references once the
  // whole file is read), so the id is taken before the emitter's own turn in document order.
  try {
    return substituteParams(node.attribute("id").value(), params_);
  } catch (const Error&) {
    return node.attribute("id").value();  // its own turn reports the undefined parameter
  }
}

void Loader::substituted(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& topLevelChild) {
  // Once per element: a shared area emitter is substituted when the first shape refers to it,
  // which may be before its own turn.
  if (!substitutedNodes_.insert(topLevelChild.internal_object()).second) return;
  substituteTree(file, topLevelChild, true);
}

void Loader::substituteTree(const std::shared_ptr<XmlFile>& file, pugi::xml_node node, bool topLevel) {
  if (node.type() != pugi::node_element) return;
  for (pugi::xml_attribute a : node.attributes()) {
    try {
      const std::string s = substituteParams(a.value(), params_);
      if (s != a.value()) a.set_value(s.c_str());
    } catch (const Error& e) {
      throw LocatedError(whereOf(*file, node) + ": attribute '" + a.name() + "': " + e.what() +
                         " (a <default> applies only to what follows it; -D name=value defines it for the whole file)");
    }
  }
  if (std::string(node.name()) == "default") {
    if (!topLevel) throw LocatedError(whereOf(*file, node) + ": <default> must be a direct child of <scene>");
    const pugi::xml_attribute name = node.attribute("name"), value = node.attribute("value");
    if (!name || !value || std::string(name.value()).empty())
      throw LocatedError(whereOf(*file, node) + ": <default> needs 'name' and 'value'");
    for (const pugi::xml_attribute& a : node.attributes())
      if (std::string(a.name()) != "name" && std::string(a.name()) != "value")
        throw LocatedError(whereOf(*file, node) + ": unsupported attribute '" + a.name() + "'");
    params_.emplace(name.value(), value.value());  // a -D define (already present) wins
    scene_.defaultNames.insert(name.value());
  }
  for (pugi::xml_node child : node.children()) substituteTree(file, child, false);
}

void Loader::sceneChild(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node) {
  const std::string tag = node.name();
  if (tag == "default") return;  // handled during substitution
  if (tag == "path") {
    // Mitsuba's <path value>: a folder prepended to the file resolver's search list; relative to
    // this file's folder first, then to the folders already listed.
    const pugi::xml_attribute value = node.attribute("value");
    if (!value || std::string(value.value()).empty()) throw LocatedError(whereOf(*file, node) + ": missing attribute 'value'");
    for (const pugi::xml_attribute& a : node.attributes())
      if (std::string(a.name()) != "value")
        throw LocatedError(whereOf(*file, node) + ": unsupported attribute '" + a.name() + "'");
    fs::path folder = value.value();
    if (folder.is_relative()) {
      fs::path found = (fs::path(file->path()).parent_path() / folder).lexically_normal();
      const std::vector<fs::path> folders = resolverFolders();
      for (auto it = folders.begin(); !fs::is_directory(found) && it != folders.end(); ++it)
        found = (*it / folder).lexically_normal();
      folder = found;
    }
    if (!fs::is_directory(folder))
      throw LocatedError(whereOf(*file, node) + ": folder '" + folder.string() + "' not found");
    searchPaths_.insert(searchPaths_.begin(), folder.string());
    return;
  }
  if (tag == "include") {
    const pugi::xml_attribute fn = node.attribute("filename");
    if (!fn) throw LocatedError(whereOf(*file, node) + ": missing attribute 'filename'");
    for (const pugi::xml_attribute& a : node.attributes())
      if (std::string(a.name()) != "filename")
        throw LocatedError(whereOf(*file, node) + ": unsupported attribute '" + a.name() + "'");
    const fs::path target = includeTarget(*file, fn.value());
    const std::string at = whereOf(*file, node);
    if (const std::string why = irregularFileReason(target.string()); !why.empty())
      throw LocatedError(at + ": included file '" + target.string() + (why == "not found" ? "' not found" : "': " + why));
    const std::string canonical = fs::weakly_canonical(target).string();
    for (const std::string& s : includeStack_)
      if (s == canonical) throw LocatedError(at + ": include cycle: '" + target.string() + "' is already being read");
    if (includeStack_.size() >= kMaxIncludeDepth)
      throw LocatedError(at + ": <include>s nested deeper than " + std::to_string(kMaxIncludeDepth) + " files");
    if (++includesRead_ > kMaxIncludes)
      throw LocatedError(at + ": more than " + std::to_string(kMaxIncludes) +
                         " <include>s read in all (files included several times count each time)");
    includeStack_.push_back(canonical);
    std::shared_ptr<XmlFile> inc;
    try {
      inc = XmlFile::load(target.string(), at);
    } catch (const LocatedError&) {
      throw;
    } catch (const Error& e) {
      throw LocatedError(e.what());  // XmlFile::load messages carry the included file's location
    }
    processFile(inc, file->location(node));
    includeStack_.pop_back();
    return;
  }
  if (tag == "bsdf") {
    buildBsdf(file, node);  // registers its id; unreferenced BSDFs never reach Scene::bsdfs
  } else if (tag == "shape") {
    buildShape(file, node);
  } else if (tag == "emitter") {
    if (areaEmitter(node.attribute("id").value()) && std::string(node.attribute("type").value()) == "area")
      return;  // built by the shapes that refer to it
    buildEmitter(file, node, -1, -1);
  } else if (tag == "sensor") {
    buildSensor(file, node);
  } else if (tag == "integrator") {
    buildIntegrator(file, node);
  } else if (tag == "texture") {
    buildTexture(file, node);  // registers its id for <ref name="..." id="..."/> in BSDFs
  } else if (tag == "sampler") {
    buildTopLevelSampler(file, node);
  } else if (tag == "medium") {
    buildMedium(file, node);  // registers its id for the shapes' and sensor's <ref>s
  } else if (tag == "volume") {
    buildVolume(file, node);
  } else if (tag == "film" || tag == "rfilter") {
    throw LocatedError(whereOf(*file, node) + ": <" + tag + "> must be inside " +
                       (tag == "rfilter" ? "<film>" : "<sensor>"));
  } else if (tag == "boolean" && std::string(node.attribute("name").value()) == "embree_use_robust_intersections") {
    // The one property Mitsuba's scene itself reads that changes how rays are traced.
    for (const pugi::xml_attribute& a : node.attributes())
      if (std::string(a.name()) != "name" && std::string(a.name()) != "value")
        throw LocatedError(whereOf(*file, node) + ": unsupported attribute '" + a.name() + "'");
    if (!node.attribute("value")) throw LocatedError(whereOf(*file, node) + ": missing attribute 'value'");
    try {
      scene_.embreeRobust = parseBoolean(node.attribute("value").value());
    } catch (const Error& e) {
      throw LocatedError(whereOf(*file, node) + ": " + e.what());
    }
  } else if (isPropertyTag(tag) || tag == "transform" || tag == "ref") {
    throw LocatedError(whereOf(*file, node) + ": <" + tag + "> is not allowed directly inside <scene>");
  } else {
    unsupported(whereOf(*file, node) + ": unknown element <" + tag + ">");
  }
}

std::vector<fs::path> Loader::resolverFolders() const {
  // Mitsuba's file resolver while a file is read: the folders of the files including it
  // (innermost first; each <include> prepends its file's folder), the <path> folders, the main
  // scene's folder.
  std::vector<fs::path> folders;
  for (auto it = includeStack_.rbegin(); it != includeStack_.rend(); ++it) folders.push_back(fs::path(*it).parent_path());
  for (const std::string& folder : searchPaths_) folders.push_back(folder);
  folders.push_back(mainDir_);
  return folders;
}

fs::path Loader::includeTarget(const XmlFile& file, const std::string& filename) const {
  // Mitsuba's <include>: relative to the including file, then through the resolver's folders.
  const fs::path name(filename);
  if (name.is_absolute()) return name.lexically_normal();
  const fs::path local = (fs::path(file.path()).parent_path() / name).lexically_normal();
  if (fs::is_regular_file(local)) return local;
  for (const fs::path& folder : resolverFolders()) {
    const fs::path candidate = (folder / name).lexically_normal();
    if (fs::is_regular_file(candidate)) return candidate;
  }
  return local;  // reported missing under the name relative to the including file
}

void Loader::unsupported(const std::string& locatedMessage) {
  if (!options_.lenient) throw LocatedError(locatedMessage);
  if (warnings_) warnings_->push_back(locatedMessage);
}

void Loader::checkUnused(const Element& e) {
  for (const std::string& name : e.props.unusedNames()) unsupported(e.whereParam(name) + ": unsupported parameter '" + name + "'");
  for (const auto& kv : e.transforms)
    if (!kv.second.used) unsupported(e.whereParam(kv.first) + ": unsupported parameter '" + kv.first + "'");
}

void Loader::unexpectedChild(const Element& parent, const pugi::xml_node& child) {
  throw LocatedError(whereOf(*parent.file, child) + ": unexpected <" + child.name() + "> inside <" + parent.tag + ">");
}

std::string Loader::resolvePath(const Element& e, const std::string& filename) const {
  const fs::path p(filename);
  if (p.is_absolute()) return p.string();
  const fs::path local = (fs::path(e.file->path()).parent_path() / p).lexically_normal();
  if (fs::exists(local)) return local.string();
  for (const std::string& folder : searchPaths_) {  // <path> folders, the latest first
    const fs::path candidate = (fs::path(folder) / p).lexically_normal();
    if (fs::exists(candidate)) return candidate.string();
  }
  // Mitsuba resolves against the main scene's folder; accept that too for included files.
  const fs::path main = (fs::path(mainDir_) / p).lexically_normal();
  if (fs::exists(main)) return main.string();
  return local.string();  // the caller reports it missing under the name users expect
}

const std::pair<std::shared_ptr<XmlFile>, pugi::xml_node>* Loader::areaEmitter(const std::string& id) const {
  auto it = areaEmitters_.find(id);
  return it == areaEmitters_.end() ? nullptr : &it->second;
}

std::string Loader::anonymousName(const std::string& type) {
  return type + "#" + std::to_string(anonymousCount_[type]++);
}

Loader::Named& Loader::registerId(const Element& e, Kind kind, BsdfPtr bsdf, TexturePtr texture) {
  if (e.id.empty()) return unnamed_ = Named();
  auto it = ids_.find(e.id);
  if (it != ids_.end()) e.fail("duplicate id '" + e.id + "' (first defined at " + it->second.where + ")");
  Named n;
  n.kind = kind;
  n.bsdf = std::move(bsdf);
  n.texture = std::move(texture);
  n.where = e.file->location(e.node);
  return ids_[e.id] = n;
}

const Loader::Named& Loader::resolveRef(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& ref) {
  for (const pugi::xml_attribute& a : ref.attributes())
    if (std::string(a.name()) != "id" && std::string(a.name()) != "name")
      throw LocatedError(whereOf(*file, ref) + ": unsupported attribute '" + a.name() + "'");
  const std::string id = ref.attribute("id").value();
  if (id.empty()) throw LocatedError(whereOf(*file, ref) + ": missing attribute 'id'");
  auto it = ids_.find(id);
  if (it == ids_.end()) throw LocatedError(whereOf(*file, ref) + ": reference to unknown id '" + id + "' (define it before use)");
  return it->second;
}

const Loader::Named& Loader::resolveRefTo(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& ref, Kind kind,
                                          const std::string& what) {
  const Named& n = resolveRef(file, ref);
  if (n.kind != kind)
    throw LocatedError(whereOf(*file, ref) + ": id '" + std::string(ref.attribute("id").value()) + "' (defined at " +
                       n.where + ") is not a " + what);
  return n;
}

}  // namespace rc
