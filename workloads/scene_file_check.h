// Checks of scene files that assimp's readers make without saying where: they run before the
// import, so a broken file is reported by its line (OBJ, glTF JSON) or byte offset (GLB),
// not by assimp's own text ("No suitable reader found", "vertex index out of range", "has no
// faces"). OBJ in scene_file_check.cpp, glTF in gltf_check.cpp.
#pragma once

#include <string>

namespace rtsim {

// Every index of an OBJ face, line or point (position, texture coordinate, normal) refers to
// an element defined above it: 1..n, or -1..-n counting back. Throws InputError naming the line.
void check_obj_indices(const std::string& path);

// A .gltf file is one JSON document (or a binary container); a .glb file (glb) is the binary
// container: its header, a length equal to the file's, and a JSON chunk first. Every triangle
// index is below its primitive's POSITION count (where the index data can be read: the GLB's
// BIN chunk, data: URIs and buffer files beside the scene). Throws InputError naming the line,
// the byte offset, or the primitive (meshes[M].primitives[P]) and the index.
void check_gltf(const std::string& path, bool glb);

}  // namespace rtsim
