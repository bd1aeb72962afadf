// Private to workloads/: scene files imported through assimp 5.2.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "traces/alpha.h"
#include "workloads/scene.h"

struct aiMaterial;
struct aiMesh;
struct aiScene;

namespace rtsim {

// Imports an OBJ+MTL, glTF 2.0, PLY, OFF or STL file into one triangle array with node
// transforms applied; points and lines are dropped. The Scene is not yet finalized. Throws
// InputError naming path for a missing file, an unsupported extension, a parse failure, a NaN
// or Inf vertex, or a file without meshes.
Scene import_scene_file(const std::string& path);

// Maps an assimp material (OBJ/MTL Phong or glTF metallic-roughness) onto rtsim's model; see
// workloads/README.md for the rules.
Material material_from_assimp(const aiMaterial& material);

// The alpha masks of a file's materials, null where a material is not alpha-tested (glTF
// alphaMode MASK), or none at all when no material is; their textures laid out one after
// another, 4 KiB aligned. Throws InputError
// naming path for a texture that cannot be read.
std::vector<std::shared_ptr<const AlphaMask>> alpha_masks(const aiScene& scene,
                                                          const std::string& path);
// The alpha of a mesh whose material has `mask`: its triangles (faces of three indices, in
// order) with their TEXCOORD_0 corners. InputError naming path if it has no texture coordinates.
std::shared_ptr<TriangleAlpha> mesh_alpha(const aiMesh& mesh, std::shared_ptr<const AlphaMask> mask,
                                          const std::string& path);

}  // namespace rtsim
