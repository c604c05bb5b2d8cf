#pragma once
// Internal state of one loadScene() call, shared by the per-plugin builders (bsdf_builder.cpp,
// shape_builder.cpp, emitter_builder.cpp, sensor_builder.cpp, integrator_builder.cpp).
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <memory>
#include <string>
#include <vector>

#include "bsdf/bsdf_textures.h"
#include "scene/element.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "scene/xml_file.h"
#include "texture/texture.h"
#include "texture/volume.h"

namespace rc {

class Loader {
 public:
  Loader(const LoadOptions& options, std::vector<std::string>* warnings);
  Scene load(const std::string& path);

  // --- used by the builders ---
  // Unsupported plugin/parameter: an error, or a warning in lenient mode (then returns normally).
  void unsupported(const std::string& locatedMessage);
  // Reports every parameter and transform of `e` that no builder read.
  void checkUnused(const Element& e);
  // Unexpected nested element: always an error (a misplaced element is a structural mistake).
  [[noreturn]] void unexpectedChild(const Element& parent, const pugi::xml_node& child);
  // Resolves a file name written in `e` relative to its XML file, then the <path> folders, then the
  // main scene's folder.
  std::string resolvePath(const Element& e, const std::string& filename) const;
  std::string anonymousName(const std::string& type);  // "<type>#<n>"

  // Objects with an id, for <ref id> and duplicate detection.
  enum class Kind { Bsdf, Emitter, Texture, Shape, ShapeGroup, Sampler, Medium, Volume, Other };
  struct Named {
    Kind kind = Kind::Other;
    BsdfPtr bsdf;
    TexturePtr texture;
    SamplerSettings sampler;  // Kind::Sampler: the settings a sensor referring to it takes
    int medium = -1;          // Kind::Medium: index into Scene::media
    VolumePtr volume;         // Kind::Volume
    int shapeGroup = -1;      // Kind::ShapeGroup: index into the loader's shape groups
    std::string where;
  };
  // Registers e's id (an element without one gets a placeholder entry nobody can refer to).
  Named& registerId(const Element& e, Kind kind, BsdfPtr bsdf = nullptr, TexturePtr texture = nullptr);
  const Named& resolveRef(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& ref);
  // resolveRef, refusing an object of another kind: "id 'x' (defined at …) is not a <what>".
  const Named& resolveRefTo(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& ref, Kind kind,
                            const std::string& what);

  BsdfPtr buildBsdf(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node);
  // Mitsuba 3's material for a shape without one: diffuse with reflectance 0.5, or 0 on the shape of
  // an area emitter (src/render/shape.cpp), so an emitter does not also reflect.
  BsdfPtr defaultBsdf(bool emitterShape = false);
  TexturePtr buildTexture(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node);
  int bsdfIndex(const BsdfPtr& bsdf);  // index into scene_.bsdfs, adding it on first use
  // Media and volumes (medium_builder.cpp, volume_builder.cpp). buildMedium returns its index in
  // Scene::media; mediumOf reads a nested <medium> or a <ref> to one.
  int buildMedium(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node);
  int mediumOf(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& child);
  VolumePtr buildVolume(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node);
  // A parameter that may be a float, an rgb or a nested volume (`nested`: name → built volume).
  VolumePtr volumeParameter(const Element& e, const std::string& name, const Color& fallback,
                            const std::map<std::string, VolumePtr>& nested) const;
  void buildShape(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node);
  // One shape into `into` (the scene, or the shapegroup `group` that holds it: then emitters and
  // nested groups or instances are errors, as in Mitsuba).
  void buildShapeInto(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node, ShapeLists& into,
                      const Element* group);
  // <shape type="shapegroup"> (returns its index) and <shape type="instance"> (instance_builder.cpp).
  int buildShapeGroup(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node);
  void buildInstance(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node);
  // Top-level emitters (shapeMesh = shapeSphere = -1) and area emitters of a shape.
  void buildEmitter(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node, int shapeMesh, int shapeSphere);
  void buildSensor(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node);
  void buildTopLevelSampler(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node);
  void useSampler(const Named& n, const std::shared_ptr<XmlFile>& file, const pugi::xml_node& ref);
  void buildIntegrator(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node);

  // Substitutes $names in a direct child of <scene> (once; later calls do nothing).
  void substituted(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& topLevelChild);
  // The top-level area emitter `id` names, or null.
  const std::pair<std::shared_ptr<XmlFile>, pugi::xml_node>* areaEmitter(const std::string& id) const;

  const LoadOptions& options() const { return options_; }
  Scene& scene() { return scene_; }

 private:
  void processFile(const std::shared_ptr<XmlFile>& file, const std::string& includedFrom);
  void substituteTree(const std::shared_ptr<XmlFile>& file, pugi::xml_node node, bool topLevel);
  std::string areaEmitterId(const pugi::xml_node& node) const;
  std::vector<std::filesystem::path> resolverFolders() const;
  std::filesystem::path includeTarget(const XmlFile& file, const std::string& filename) const;
  void sceneChild(const std::shared_ptr<XmlFile>& file, const pugi::xml_node& node);

  LoadOptions options_;
  std::vector<std::string>* warnings_;
  std::map<std::string, std::string> params_;  // -D defines, then <default>s not overridden
  std::vector<std::string> includeStack_;      // canonical paths of the files being read
  size_t includesRead_ = 0;
  std::vector<std::shared_ptr<XmlFile>> files_;
  std::string mainDir_;
  std::vector<std::string> searchPaths_;       // <path value> folders, the latest first
  std::map<std::string, Named> ids_;
  Named unnamed_;                               // registerId's answer for elements without an id
  // Top-level <emitter type="area" id> of each file read: Mitsuba attaches them to the shapes that
  // <ref> them, also from before their definition.
  std::map<std::string, std::pair<std::shared_ptr<XmlFile>, pugi::xml_node>> areaEmitters_;
  std::set<const void*> substitutedNodes_;     // top-level elements already substituted
  std::map<const Bsdf*, int> bsdfIndices_;
  BsdfPtr defaultBsdf_[2];  // [emitterShape]
  // Per built BSDF: its nesting depth and how many BSDFs one evaluation visits, counting a BSDF
  // that <ref>s reach twice twice (bsdf_builder.cpp bounds both).
  struct BsdfTreeSize {
    int depth = 1;
    uint64_t nodes = 1;
  };
  std::map<const Bsdf*, BsdfTreeSize> bsdfTreeSizes_;
  // Per built BSDF: the mesh attributes its mesh_attribute textures (its own and its nested
  // BSDFs') read; a shape with that BSDF must carry them (shape_builder.cpp).
  std::map<const Bsdf*, std::vector<std::string>> meshAttributesRead_;
  void checkMeshAttributes(const Element& shape, const BsdfPtr& bsdf, const Mesh* mesh) const;
  // The steps of buildBsdf (bsdf_builder.cpp).
  void collectBsdfChildren(const std::shared_ptr<XmlFile>& file, const Element& e, std::vector<BsdfPtr>& nested,
                           std::vector<std::pair<pugi::xml_node, TexturePtr>>& textures);
  BsdfTreeSize bsdfTreeOf(const Element& e, const std::vector<BsdfPtr>& nested) const;
  void applyBsdfTextures(const std::shared_ptr<XmlFile>& file, Element& e,
                         const std::vector<std::pair<pugi::xml_node, TexturePtr>>& textures, TexturePtr& factor,
                         BsdfTextures& perPoint);
  std::vector<ShapeLists> shapeGroups_;  // in their own space; instances place copies in scene_
  size_t instancedPrimitives_ = 0;       // what the instances have placed so far (bounded)
  std::map<std::string, int> anonymousCount_;
  int sensors_ = 0, integrators_ = 0, environments_ = 0;
  Scene scene_;
};

}  // namespace rc
