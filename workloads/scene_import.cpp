// Scene files through assimp: checks the file, imports without post-processing to check the raw
// vertices, then triangulates and welds, and walks the node hierarchy: each mesh kept once in
// object space, each node's reference to it an instance (Scene::instanced), or one instance per
// element of the node's glTF EXT_mesh_gpu_instancing attributes, which assimp 5.2 ignores and
// gltf_check.cpp reads. A file that places each mesh once is also flattened into one world-space
// triangle array (each mesh reference transformed by its node's accumulated matrix); one that
// reuses a mesh keeps only its instances (workloads/scene.h). Cameras and lights are read before
// post-processing removes them.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <unordered_map>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>

#include "traces/error.h"
#include "workloads/scene_file_check.h"
#include "workloads/scene_import.h"
#include "workloads/scene_import_log.h"

namespace rtsim {
namespace {

namespace fs = std::filesystem;

// Formats whose files carry no materials: they get one default material.
bool has_materials(const std::string& ext) {
  return ext == ".obj" || ext == ".gltf" || ext == ".glb";
}

std::string supported_list() {
  std::string list;
  for (const auto& e : scene_file_extensions()) list += (list.empty() ? "" : ", ") + e;
  return list;
}

std::string checked_extension(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw_input_error(path, "", "no such file");
  if (fs::is_directory(path, ec)) throw_input_error(path, "", "is a directory, not a scene file");
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  auto known = scene_file_extensions();
  if (std::find(known.begin(), known.end(), ext) == known.end())
    throw_input_error(
        path, "", "unsupported scene file extension '" + ext + "'; supported: " + supported_list());
  return ext;
}

// Checks the meshes as the reader produced them, before any post-processing can hide a problem.
// A vertex index is the reader's: the file's for PLY and OFF, the face corner's for OBJ and STL.
void check_raw_meshes(const std::string& path, const aiScene& scene) {
  size_t polygons = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) polygons += mesh.mFaces[f].mNumIndices >= 3;
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      std::string problem = point_problem({p.x, p.y, p.z});
      if (problem.empty()) continue;
      std::string where;
      if (scene.mNumMeshes > 1 || mesh.mName.length > 0) {
        where = mesh.mName.length > 0 ? "mesh '" + std::string(mesh.mName.C_Str()) + "' "
                                      : "mesh " + std::to_string(m) + " ";
      }
      throw_input_error(path, where + "vertex " + std::to_string(v), "position " + problem);
    }
  }
  if (polygons == 0) throw_input_error(path, "", "the file has no triangles");
}

// The PLY, OFF and STL readers log an error when they repair broken geometry (an index clamped,
// a short vertex list padded with zeros) and carry on; the OBJ reader logs errors for harmless
// layout quirks (the Cornell box's usemtl before its first g), and the OBJ and glTF readers throw
// on real damage. So a logged error fails the import only for the geometry-only formats.
void check_log(const std::string& path, const std::string& ext, const AssimpErrorLog& log) {
  if (has_materials(ext) || log.errors().empty()) return;
  throw_input_error(path, "", "cannot import: " + log.errors().front());
}

bool has_triangles(const aiMesh& mesh) {
  for (unsigned f = 0; f < mesh.mNumFaces; ++f)
    if (mesh.mFaces[f].mNumIndices == 3) return true;
  return false;
}

aiMatrix4x4 to_assimp(const Transform& t) {
  const glm::mat3& m = t.linear;
  return aiMatrix4x4(m[0][0], m[1][0], m[2][0], t.offset.x, m[0][1], m[1][1], m[2][1], t.offset.y,
                     m[0][2], m[1][2], m[2][2], t.offset.z, 0.0f, 0.0f, 0.0f, 1.0f);
}

// The EXT_mesh_gpu_instancing instances of the aiNodes assimp made of glTF nodes.
using GpuInstances = std::unordered_map<const aiNode*, const std::vector<Transform>*>;

// assimp names an unnamed glTF node by an id whose form changes between versions ("nodes[3]" in
// 5.2, "nodes_3" later), and glTF names need not be unique, so the nodes are matched by position:
// assimp builds its tree child for child from the scene's, under a "ROOT" node it adds when the
// scene has several root nodes.
void match_gltf_node(const aiNode& node, size_t index, const GltfNodeTree& tree,
                     const std::string& path, GpuInstances& out);

[[noreturn]] void node_tree_mismatch(const std::string& path) {
  throw_input_error(path, "",
                    "assimp's node tree differs from the file's, so rtsim cannot place its "
                    "EXT_mesh_gpu_instancing instances");
}

void match_gltf_children(const aiNode& parent, const std::vector<size_t>& children,
                         const GltfNodeTree& tree, const std::string& path, GpuInstances& out) {
  if (parent.mNumChildren != children.size()) node_tree_mismatch(path);
  for (unsigned c = 0; c < parent.mNumChildren; ++c)
    match_gltf_node(*parent.mChildren[c], children[c], tree, path, out);
}

void match_gltf_node(const aiNode& node, size_t index, const GltfNodeTree& tree,
                     const std::string& path, GpuInstances& out) {
  if (index >= tree.nodes.size()) node_tree_mismatch(path);
  const GltfNode& gltf = tree.nodes[index];
  if (gltf.gpu_instances) out[&node] = &*gltf.gpu_instances;
  match_gltf_children(node, gltf.children, tree, path, out);
}

GpuInstances match_gpu_instances(const aiScene& scene, const GltfNodeTree& tree,
                                 const std::string& path) {
  GpuInstances out;
  if (!tree.has_gpu_instances()) return out;
  if (tree.roots.size() == 1)
    match_gltf_node(*scene.mRootNode, tree.roots[0], tree, path, out);
  else
    match_gltf_children(*scene.mRootNode, tree.roots, tree, path, out);
  return out;
}

// Walks the node hierarchy: each mesh reference with triangles becomes an instance of the mesh
// (kept once, in object space), or one per EXT_mesh_gpu_instancing instance of its node; if no
// mesh is placed twice, the walk also appends the transformed triangles to the flattened mesh,
// else the scene keeps its instances only.
class SceneWalk {
 public:
  SceneWalk(const aiScene& scene, Scene& out, const GpuInstances& gpu_instances, bool use_materials,
            const std::vector<std::shared_ptr<const AlphaMask>>& masks, std::string path)
      : scene_(scene),
        out_(out),
        gpu_instances_(gpu_instances),
        use_materials_(use_materials),
        masks_(masks),
        path_(std::move(path)),
        fallback_name_(fs::path(path_).stem().string()) {
    std::vector<size_t> placed(scene.mNumMeshes, 0);
    count_placements(*scene.mRootNode, placed);
    flatten_ = std::all_of(placed.begin(), placed.end(), [](size_t n) { return n <= 1; });
    if (flatten_ && !masks.empty())
      out_.mesh.alpha = flat_alpha_ = std::make_shared<TriangleAlpha>();
  }

  void walk(const aiNode& node, const aiMatrix4x4& parent) {
    aiMatrix4x4 transform = parent * node.mTransformation;
    for (const aiMatrix4x4& placement : placements(node, transform))
      for (unsigned i = 0; i < node.mNumMeshes; ++i) place_mesh(node, i, placement);
    for (unsigned c = 0; c < node.mNumChildren; ++c) walk(*node.mChildren[c], transform);
  }

 private:
  const std::vector<Transform>* gpu_instances(const aiNode& node) const {
    auto it = gpu_instances_.find(&node);
    return it == gpu_instances_.end() ? nullptr : it->second;
  }

  // How many times the node hierarchy places each mesh.
  void count_placements(const aiNode& node, std::vector<size_t>& placed) const {
    const std::vector<Transform>* instances = gpu_instances(node);
    for (unsigned i = 0; i < node.mNumMeshes; ++i)
      placed[node.mMeshes[i]] += instances ? instances->size() : 1;
    for (unsigned c = 0; c < node.mNumChildren; ++c) count_placements(*node.mChildren[c], placed);
  }

  // Where the node places its meshes: at its world transform, or at each of its
  // EXT_mesh_gpu_instancing instances in its frame.
  std::vector<aiMatrix4x4> placements(const aiNode& node, const aiMatrix4x4& world) const {
    const std::vector<Transform>* instances = gpu_instances(node);
    if (!instances) return {world};
    std::vector<aiMatrix4x4> out;
    out.reserve(instances->size());
    for (const Transform& instance : *instances) out.push_back(world * to_assimp(instance));
    return out;
  }

  // The node's mesh reference i, placed by transform: an instance, and flattened triangles.
  void place_mesh(const aiNode& node, unsigned i, const aiMatrix4x4& transform) {
    const aiMesh& mesh = *scene_.mMeshes[node.mMeshes[i]];
    if (!has_triangles(mesh)) return;  // points and lines only
    uint32_t material = use_materials_ ? mesh.mMaterialIndex : 0;
    uint32_t object = object_id(object_name(node, i));
    const TriangleMesh& unique = add_instance(node.mMeshes[i], transform, material, object);
    if (!flatten_) return;
    size_t added = append_triangles(mesh, transform, out_.mesh);
    if (flat_alpha_) append_alpha(*flat_alpha_, unique.alpha.get(), added);
    out_.material_ids.insert(out_.material_ids.end(), added, material);
    out_.object_ids.insert(out_.object_ids.end(), added, object);
  }

  // An object is the named node (OBJ o/g groups, glTF nodes), else the mesh, else the file.
  std::string object_name(const aiNode& node, unsigned i) const {
    if (&node != scene_.mRootNode && node.mName.length > 0) return node.mName.C_Str();
    const aiMesh& mesh = *scene_.mMeshes[node.mMeshes[i]];
    return mesh.mName.length > 0 ? mesh.mName.C_Str() : fallback_name_;
  }

  uint32_t object_id(const std::string& name) {
    auto [it, inserted] = object_ids_.try_emplace(name, uint32_t(out_.object_names.size()));
    if (inserted) out_.object_names.push_back(name);
    return it->second;
  }

  // Appends the mesh's triangles and the vertices they use, in order of first use, to `into`;
  // the number of triangles.
  static size_t append_triangles(const aiMesh& mesh, const aiMatrix4x4& transform,
                                 TriangleMesh& into) {
    constexpr uint32_t kUnused = ~0u;
    std::vector<uint32_t> remap(mesh.mNumVertices, kUnused);
    size_t added = 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines
      std::array<uint32_t, 3> tri;
      for (int k = 0; k < 3; ++k) {
        uint32_t& index = remap[face.mIndices[k]];
        if (index == kUnused) {
          index = uint32_t(into.positions.size());
          aiVector3D p = transform * mesh.mVertices[face.mIndices[k]];
          into.positions.emplace_back(p.x, p.y, p.z);
        }
        tri[k] = index;
      }
      into.triangles.push_back(tri);
      ++added;
    }
    return added;
  }

  // The file's mesh reference as an instance: its mesh kept once, in object space (with its
  // material's alpha mask); the mesh.
  const TriangleMesh& add_instance(unsigned mesh_index, const aiMatrix4x4& m, uint32_t material,
                                   uint32_t object) {
    auto [it, inserted] =
        unique_mesh_.try_emplace(mesh_index, uint32_t(out_.instanced.meshes.size()));
    if (inserted) {
      const aiMesh& mesh = *scene_.mMeshes[mesh_index];
      TriangleMesh& unique = out_.instanced.meshes.emplace_back();
      size_t added = append_triangles(mesh, aiMatrix4x4(), unique);
      if (!masks_.empty() && masks_[material])
        unique.alpha = mesh_alpha(mesh, masks_[material], path_);
      if (!flatten_) out_.mesh_material_ids.emplace_back(added, material);
    }
    Instance instance;
    instance.mesh = it->second;
    instance.to_world.linear = glm::mat3(m.a1, m.b1, m.c1, m.a2, m.b2, m.c2, m.a3, m.b3, m.c3);
    instance.to_world.offset = {m.a4, m.b4, m.c4};
    out_.instanced.instances.push_back(instance);
    if (!flatten_) out_.instance_object_ids.push_back(object);
    return out_.instanced.meshes[it->second];
  }

  const aiScene& scene_;
  Scene& out_;
  const GpuInstances& gpu_instances_;
  bool use_materials_;
  const std::vector<std::shared_ptr<const AlphaMask>>& masks_;  // per material, or none
  std::string path_;
  std::string fallback_name_;
  bool flatten_ = true;
  std::shared_ptr<TriangleAlpha> flat_alpha_;  // the flattened mesh's, if a material has a mask
  std::unordered_map<std::string, uint32_t> object_ids_;
  std::unordered_map<unsigned, uint32_t> unique_mesh_;  // assimp mesh -> instanced.meshes
};

aiMatrix4x4 world_transform(const aiScene& scene, const aiString& node_name) {
  aiMatrix4x4 m;
  for (const aiNode* n = scene.mRootNode->FindNode(node_name); n; n = n->mParent)
    m = n->mTransformation * m;
  return m;
}

glm::vec3 to_glm(const aiVector3D& v) {
  return {v.x, v.y, v.z};
}

glm::vec3 direction(const aiMatrix4x4& m, const aiVector3D& v) {
  aiVector3D d = aiMatrix3x3(m) * v;
  return d.Length() > 0.0f ? to_glm(d.Normalize()) : glm::vec3(0.0f, 0.0f, -1.0f);
}

// The file's cameras and lights, placed by their nodes. Cameras (only glTF has them) sit at
// their node's origin: assimp 5.2 also copies the node's translation into mPosition, which would
// count it twice. It gives the horizontal field of view as yfov x aspect (yfov alone when the
// aspect is unset); an orthographic camera as its half width (xmag) and xmag / ymag as the
// aspect, with no field of view.
void read_cameras_and_lights(const aiScene& scene, Scene& out) {
  for (unsigned i = 0; i < scene.mNumCameras; ++i) {
    const aiCamera& c = *scene.mCameras[i];
    aiMatrix4x4 m = world_transform(scene, c.mName);
    SceneCamera cam;
    cam.name = c.mName.C_Str();
    cam.position = to_glm(m * aiVector3D(0.0f, 0.0f, 0.0f));
    cam.forward = direction(m, c.mLookAt);
    cam.up = direction(m, c.mUp);
    cam.orthographic = c.mOrthographicWidth > 0.0f;
    if (cam.orthographic) {
      cam.xmag = c.mOrthographicWidth;
      cam.ymag = c.mAspect > 0.0f ? c.mOrthographicWidth / c.mAspect : c.mOrthographicWidth;
    }
    float yfov = c.mAspect > 0.0f ? c.mHorizontalFOV / c.mAspect : c.mHorizontalFOV;
    if (yfov > 0.0f) cam.yfov_degrees = yfov * 180.0f / 3.14159265f;
    out.cameras.push_back(cam);
  }
  for (unsigned i = 0; i < scene.mNumLights; ++i) {
    const aiLight& l = *scene.mLights[i];
    aiMatrix4x4 m = world_transform(scene, l.mName);
    SceneLight light;
    if (l.mType == aiLightSource_DIRECTIONAL)
      light.type = SceneLight::Type::Directional;
    else if (l.mType == aiLightSource_SPOT)
      light.type = SceneLight::Type::Spot;
    else if (l.mType != aiLightSource_POINT)
      continue;  // area and ambient lights: not punctual
    light.name = l.mName.C_Str();
    light.position = to_glm(m * l.mPosition);
    light.direction = direction(m, l.mDirection);
    light.color = {l.mColorDiffuse.r, l.mColorDiffuse.g, l.mColorDiffuse.b};
    if (l.mAngleOuterCone > 0.0f)
      light.outer_cone_degrees = l.mAngleOuterCone * 180.0f / 3.14159265f;
    out.lights.push_back(light);
  }
}

}  // namespace

std::vector<std::string> scene_file_extensions() {
  return {".obj", ".gltf", ".glb", ".ply", ".off", ".stl"};
}

Scene import_scene_file(const std::string& path) {
  const std::string ext = checked_extension(path);
  if (ext == ".obj") check_obj_indices(path);
  GltfNodeTree gltf_nodes;
  if (ext == ".gltf" || ext == ".glb") gltf_nodes = check_gltf(path, ext == ".glb");
  Assimp::Importer importer;
  AssimpErrorLog log;
  const aiScene* raw = importer.ReadFile(path, 0);
  if (!raw) throw_input_error(path, "", std::string("cannot import: ") + importer.GetErrorString());
  check_log(path, ext, log);
  check_raw_meshes(path, *raw);
  Scene out;
  read_cameras_and_lights(*raw, out);
  const bool use_materials = has_materials(ext) && raw->mNumMaterials > 0;
  std::vector<std::shared_ptr<const AlphaMask>> masks;
  if (use_materials) masks = alpha_masks(*raw, path);
  // Only positions matter, and texture coordinates where a material has an alpha mask; dropping
  // the rest lets the weld merge vertices by position (and texture coordinates) alone.
  int dropped = aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS | aiComponent_COLORS |
                aiComponent_TEXCOORDS | aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS |
                aiComponent_LIGHTS | aiComponent_CAMERAS | aiComponent_TEXTURES;
  if (!masks.empty()) dropped &= ~aiComponent_TEXCOORDS;
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, dropped);
  const aiScene* scene =
      importer.ApplyPostProcessing(aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                                   aiProcess_RemoveComponent | aiProcess_JoinIdenticalVertices);
  if (!scene)
    throw_input_error(path, "", std::string("invalid data: ") + importer.GetErrorString());
  check_log(path, ext, log);

  out.source = path;
  if (use_materials) {
    for (unsigned m = 0; m < scene->mNumMaterials; ++m)
      out.materials.push_back(material_from_assimp(*scene->mMaterials[m]));
  } else {
    out.materials.push_back(Material{"default"});
  }
  GpuInstances gpu_instances = match_gpu_instances(*scene, gltf_nodes, path);
  SceneWalk(*scene, out, gpu_instances, use_materials, masks, path)
      .walk(*scene->mRootNode, aiMatrix4x4());
  if (out.instanced.instances.empty()) throw_input_error(path, "", "the file has no triangles");
  return out;
}

}  // namespace rtsim
