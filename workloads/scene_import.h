// Private to workloads/: scene files imported through assimp 5.2.
#pragma once

#include <string>

#include "workloads/scene.h"

struct aiMaterial;

namespace rtsim {

// Imports an OBJ+MTL, glTF 2.0, PLY, OFF or STL file into one triangle array with node
// transforms applied; points and lines are dropped. The Scene is not yet finalized. Throws
// InputError naming path for a missing file, an unsupported extension, a parse failure, a NaN
// or Inf vertex, or a file without meshes.
Scene import_scene_file(const std::string& path);

// Maps an assimp material (OBJ/MTL Phong or glTF metallic-roughness) onto rtsim's model; see
// workloads/README.md for the rules.
Material material_from_assimp(const aiMaterial& material);

}  // namespace rtsim
