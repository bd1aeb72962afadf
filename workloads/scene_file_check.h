// Checks of scene files that assimp's readers make without saying where: they run before the
// import, so a broken file is reported by its line (OBJ, glTF JSON) or byte offset (GLB),
// not by assimp's own text ("No suitable reader found", "vertex index out of range", "has no
// faces"). OBJ in scene_file_check.cpp, glTF in gltf_check.cpp, which also reads the glTF node
// tree's EXT_mesh_gpu_instancing instances that assimp 5.2 ignores.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "traces/instances.h"

namespace rtsim {

// Every index of an OBJ face, line or point (position, texture coordinate, normal) refers to
// an element defined above it: 1..n, or -1..-n counting back. Throws InputError naming the line.
void check_obj_indices(const std::string& path);

// A glTF node as far as assimp 5.2 does not read it: its children and its
// EXT_mesh_gpu_instancing instances, each the translation x rotation x scale that places the
// node's mesh in the node's frame (none: the node places its mesh once, as without the extension).
struct GltfNode {
  std::vector<size_t> children;
  std::optional<std::vector<Transform>> gpu_instances;
};

// The node tree of the scene a glTF file shows (its "scene", else scene 0, as assimp picks it).
struct GltfNodeTree {
  std::vector<size_t> roots;
  std::vector<GltfNode> nodes;  // by glTF node index

  bool has_gpu_instances() const;
};

// A .gltf file is one JSON document (or a binary container); a .glb file (glb) is the binary
// container: its header, a length equal to the file's, and a JSON chunk first. Every triangle
// index is below its primitive's POSITION count (where the index data can be read: the GLB's
// BIN chunk, data: URIs and buffer files beside the scene). Throws InputError naming the line,
// the byte offset, or the primitive (meshes[M].primitives[P]) and the index. Returns the node
// tree, with the EXT_mesh_gpu_instancing instances read: an attribute whose accessor is missing,
// of the wrong type or component type, sparse, unreadable, of another count than the node's
// other attributes, or with NaN or Inf values throws InputError naming the place ("node N
// EXT_mesh_gpu_instancing TRANSLATION"), as do more instances than the memory available holds.
// The node hierarchy must be disjoint trees, as glTF says: a node with two parents or listed
// twice by one, a cycle, a missing child, or a scene root that is a child throws InputError
// naming the nodes. JSON nested deeper than 256 levels or nodes deeper than 1000 throw too:
// assimp reads both recursively.
GltfNodeTree check_gltf(const std::string& path, bool glb);

}  // namespace rtsim
