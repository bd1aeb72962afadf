// Alpha-tested materials of scene files (glTF alphaMode MASK): a mask per material from its base
// colour texture's alpha (through workloads/alpha_image.h) times its base colour factor's alpha,
// and the texture coordinates (TEXCOORD_0) of the triangles that use it.
#include <cmath>
#include <filesystem>

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <fmt/format.h>

#include "traces/error.h"
#include "workloads/alpha_image.h"
#include "workloads/scene_import.h"

namespace rtsim {
namespace {

constexpr uint64_t kTextureAlign = 4096;  // each texture starts on its own page

bool alpha_tested(const aiMaterial& m) {
  aiString mode;
  return m.Get(AI_MATKEY_GLTF_ALPHAMODE, mode) == AI_SUCCESS && std::string(mode.C_Str()) == "MASK";
}

// The base colour texture's alpha: embedded (a compressed file or raw texels) or a file beside
// the scene; an image of one opaque texel when the material has none.
AlphaImage base_colour_alpha(const aiScene& scene, const aiMaterial& m, const std::string& path,
                             const std::string& material) {
  aiString file;
  unsigned uv_set = 0;
  if (m.GetTexture(aiTextureType_BASE_COLOR, 0, &file, nullptr, &uv_set) != AI_SUCCESS &&
      m.GetTexture(aiTextureType_DIFFUSE, 0, &file, nullptr, &uv_set) != AI_SUCCESS)
    return {1, 1, {255}};
  if (uv_set != 0)
    throw_input_error(path, "material '" + material + "'",
                      fmt::format("its base colour texture uses TEXCOORD_{}; rtsim reads only "
                                  "TEXCOORD_0 for alpha masks",
                                  uv_set));
  const aiTexture* embedded = scene.GetEmbeddedTexture(file.C_Str());
  if (!embedded) {
    auto image = std::filesystem::path(path).parent_path() / file.C_Str();
    return read_alpha_image(image.string(), {});
  }
  if (embedded->mHeight == 0) {
    const auto* bytes = reinterpret_cast<const uint8_t*>(embedded->pcData);
    std::string name =
        fmt::format("{} (embedded texture {}.{})", path, file.C_Str(), embedded->achFormatHint);
    return read_alpha_image(name, {bytes, bytes + embedded->mWidth});
  }
  AlphaImage image{embedded->mWidth, embedded->mHeight, {}};
  for (size_t i = 0; i < size_t(image.width) * image.height; ++i)
    image.alpha.push_back(embedded->pcData[i].a);
  return image;
}

}  // namespace

std::vector<std::shared_ptr<const AlphaMask>> alpha_masks(const aiScene& scene,
                                                          const std::string& path) {
  std::vector<std::shared_ptr<const AlphaMask>> masks(scene.mNumMaterials);
  bool any = false;
  uint64_t texture_end = 0;
  for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
    const aiMaterial& m = *scene.mMaterials[i];
    if (!alpha_tested(m)) continue;
    aiString name;
    m.Get(AI_MATKEY_NAME, name);
    auto mask = std::make_shared<AlphaMask>();
    mask->name = fmt::format("{} material '{}'", path, name.C_Str());
    AlphaImage image = base_colour_alpha(scene, m, path, name.C_Str());
    aiColor4D factor(1.0f, 1.0f, 1.0f, 1.0f);
    m.Get(AI_MATKEY_BASE_COLOR, factor);
    ai_real cutoff = 0.5f;
    m.Get(AI_MATKEY_GLTF_ALPHACUTOFF, cutoff);
    mask->cutoff = float(cutoff);
    mask->width = image.width;
    mask->height = image.height;
    mask->alpha.reserve(image.alpha.size());
    for (uint8_t a : image.alpha)
      mask->alpha.push_back(uint8_t(std::lround(std::clamp(float(a) * factor.a, 0.0f, 255.0f))));
    mask->texture_offset = texture_end;
    uint64_t bytes = uint64_t(kTexelBytes) * image.width * image.height;
    texture_end += (bytes + kTextureAlign - 1) / kTextureAlign * kTextureAlign;
    masks[i] = std::move(mask);
    any = true;
  }
  if (!any) masks.clear();
  return masks;
}

std::shared_ptr<TriangleAlpha> mesh_alpha(const aiMesh& mesh, std::shared_ptr<const AlphaMask> mask,
                                          const std::string& path) {
  if (!mesh.mTextureCoords[0])
    throw_input_error(path, "mesh '" + std::string(mesh.mName.C_Str()) + "'",
                      "its material is alphaMode MASK but it has no TEXCOORD_0");
  auto alpha = std::make_shared<TriangleAlpha>();
  alpha->masks = {std::move(mask)};
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;  // as append_triangles
    std::array<glm::vec2, 3> uv;
    for (int k = 0; k < 3; ++k) {
      const aiVector3D& c = mesh.mTextureCoords[0][face.mIndices[k]];
      uv[k] = {c.x, 1.0f - c.y};  // assimp turns glTF's v down into v up: back to glTF's
    }
    alpha->uv.push_back(uv);
    alpha->mask_of.push_back(0);
  }
  return alpha;
}

}  // namespace rtsim
