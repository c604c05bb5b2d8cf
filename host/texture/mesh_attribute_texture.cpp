// Mitsuba 3's mesh_attribute texture (src/textures/mesh_attribute.cpp, Mesh::eval_attribute in its
// RGB variants): the named attribute of the mesh at the surface point, a vertex attribute blended
// with the triangle's barycentrics, a face attribute constant over the face; one value is grey,
// three are RGB, any other count is black; times `scale`.
#include "texture/texture.h"

namespace rc {
namespace {

class MeshAttributeTexture final : public Texture {
 public:
  MeshAttributeTexture(std::string name, float scale) : name_(std::move(name)), scale_(scale) {}

  Color eval(const TexturePoint& point) const override {
    const MeshAttribute* attribute = find(point.attributes);
    if (!attribute || (attribute->channels != 1 && attribute->channels != 3)) return Color(0.0f);
    const size_t n = static_cast<size_t>(attribute->channels);
    const float* v = attribute->values.data();
    Color c(0.0f);
    if (attribute->perFace) {
      for (size_t k = 0; k < n; ++k) c[k] = v[point.face * n + k];
    } else {
      const float w[3] = {1.0f - point.bary.x - point.bary.y, point.bary.x, point.bary.y};
      for (int corner = 0; corner < 3; ++corner)
        for (size_t k = 0; k < n; ++k) c[k] += w[corner] * v[point.vertices[corner] * n + k];
    }
    if (n == 1) c = Color(c[0]);
    return scale_ * c;
  }
  // Not known before a shape carries it; stands in only where a parameter needs a value at load
  // (the loader allows this texture only on factor parameters, which are built at 1).
  Color mean() const override { return Color(0.5f * scale_); }
  std::string meshAttribute() const override { return name_; }

 private:
  const MeshAttribute* find(const MeshAttributes* attributes) const {
    if (!attributes) return nullptr;
    for (const MeshAttribute& a : *attributes)
      if (a.name == name_) return &a;
    return nullptr;
  }
  std::string name_;
  float scale_;
};

}  // namespace

TexturePtr makeMeshAttributeTexture(const std::string& name, float scale) {
  return std::make_shared<MeshAttributeTexture>(name, scale);
}

}  // namespace rc
