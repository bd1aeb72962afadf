// The glTF 2.0 checks of scene_file_check.h: the GLB container, the JSON document, and every
// triangle index against its primitive's POSITION count (assimp drops the faces of a primitive
// with an index out of range and then reports only that the mesh "has no faces"); and the node
// tree with the EXT_mesh_gpu_instancing instances, which assimp 5.2 ignores.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <utility>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "traces/error.h"
#include "traces/memory_plan.h"
#include "workloads/scene_file_check.h"

namespace rtsim {
namespace {

using Json = nlohmann::json;

std::string read_whole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_input_error(path, "", "cannot open the scene file");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

uint32_t word_at(const std::string& data, size_t offset) {
  uint32_t v = 0;
  std::memcpy(&v, data.data() + offset, 4);  // little-endian, as glTF's binary data is
  return v;
}

// RFC 4648 base64 into out; false on a character outside the alphabet.
bool base64_decode(const std::string& text, std::string& out) {
  static const std::string kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  uint32_t bits = 0;
  int count = 0;
  for (char c : text) {
    if (c == '=') break;
    size_t v = kAlphabet.find(c);
    if (v == std::string::npos) return false;
    bits = (bits << 6) | uint32_t(v);
    if ((count += 6) >= 8) {
      count -= 8;
      out.push_back(char((bits >> count) & 0xff));
    }
  }
  return true;
}

// The file's JSON document and, for a GLB, its BIN chunk. Throws InputError for a broken
// container, naming the byte offset.
struct GltfFile {
  std::string json, bin;
  size_t json_offset = 0;
  bool binary = false;
};

GltfFile read_container(const std::string& path, bool glb) {
  GltfFile f;
  std::string data = read_whole(path);
  f.binary = data.size() >= 4 && data.compare(0, 4, "glTF") == 0;
  if (!f.binary && glb)
    throw_input_error(path, "offset 0", "not a GLB file (it does not begin with 'glTF')");
  if (!f.binary) {
    f.json = std::move(data);
    return f;
  }
  if (data.size() < 20)
    throw_input_error(path, "",
                      fmt::format("a GLB file of {} bytes is shorter than its 12-byte header and "
                                  "first chunk header",
                                  data.size()));
  if (word_at(data, 4) != 2)
    throw_input_error(path, "offset 4",
                      fmt::format("GLB version {}; rtsim reads glTF 2.0", word_at(data, 4)));
  if (word_at(data, 8) != data.size())
    throw_input_error(path, "offset 8",
                      fmt::format("the header says {} bytes, the file has {} (truncated?)",
                                  word_at(data, 8), data.size()));
  if (word_at(data, 16) != 0x4E4F534Au)
    throw_input_error(path, "offset 16", "the first chunk is not the JSON chunk");
  size_t offset = 12;
  for (int chunk = 0; offset + 8 <= data.size(); ++chunk) {
    uint64_t length = word_at(data, offset);
    if (offset + 8 + length > data.size())
      throw_input_error(path, fmt::format("offset {}", offset),
                        fmt::format("a chunk of {} bytes runs past the end of the file", length));
    std::string body = data.substr(offset + 8, length);
    if (chunk == 0) {
      f.json = body;
      f.json_offset = offset + 8;
    } else if (word_at(data, offset + 4) == 0x004E4942u && f.bin.empty()) {
      f.bin = body;
    }
    offset += 8 + length;
  }
  return f;
}

// Where byte `byte` of the JSON document lies: its line, or the file offset in a GLB.
std::string place_of(const GltfFile& f, size_t byte) {
  if (f.binary) return fmt::format("offset {}", f.json_offset + byte);
  return fmt::format("line {}", 1 + std::count(f.json.begin(), f.json.begin() + byte, '\n'));
}

// assimp parses the JSON recursively (RapidJSON's default), so deep nesting would overflow
// its stack: no glTF document comes near this.
constexpr int kMaxJsonDepth = 256;

void check_json_nesting(const std::string& path, const GltfFile& f) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (size_t i = 0; i < f.json.size(); ++i) {
    char c = f.json[i];
    if (in_string) {
      in_string = escaped || c != '"';
      escaped = !escaped && c == '\\';
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw_input_error(path, place_of(f, i),
                          fmt::format("JSON nested deeper than {} levels; rtsim reads glTF "
                                      "documents up to that depth",
                                      kMaxJsonDepth));
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

Json parse_document(const std::string& path, const GltfFile& f) {
  check_json_nesting(path, f);
  try {
    return Json::parse(f.json);
  } catch (const Json::parse_error& e) {
    size_t byte = e.byte == 0 ? 0 : std::min<size_t>(e.byte - 1, f.json.size());
    std::string what = e.what();
    size_t colon = what.find(": ", what.find("parse error"));
    std::string reason = colon == std::string::npos ? what : what.substr(colon + 2);
    throw_input_error(path, place_of(f, byte), "not valid JSON: " + reason);
  }
}

// The JSON document and its buffers, each loaded on first use.
class GltfDocument {
 public:
  GltfDocument(const std::string& path, const GltfFile& f, const Json& doc)
      : path_(path), file_(f), doc_(doc) {}

  const std::string& path() const { return path_; }

  // The document's array `key`; empty if it has none.
  const Json& member(const char* key) const {
    static const Json kEmpty = Json::array();
    auto it = doc_.find(key);
    return it != doc_.end() && it->is_array() ? *it : kEmpty;
  }

  // The element of array `array` that `index` names; nullptr if it names none.
  const Json* element(const char* array, const Json& index) const {
    const Json& a = member(array);
    if (!index.is_number_unsigned() || index.get<size_t>() >= a.size()) return nullptr;
    return &a[index.get<size_t>()];
  }

  // Buffer i's bytes; nullptr if there is no such buffer or it cannot be read (an external file
  // that is missing, a broken data: URI).
  const std::string* buffer(size_t i) {
    if (loaded_.count(i)) return &loaded_[i];
    const Json* b = element("buffers", Json(i));
    if (!b) return nullptr;
    std::string data;
    std::string uri = b->value("uri", "");
    if (uri.empty()) {
      if (i != 0 || !file_.binary) return nullptr;
      data = file_.bin;
    } else if (uri.rfind("data:", 0) == 0) {
      size_t comma = uri.find(";base64,");
      if (comma == std::string::npos || !base64_decode(uri.substr(comma + 8), data)) return nullptr;
    } else {
      auto file = std::filesystem::path(path_).parent_path() / uri;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(file, ec)) return nullptr;
      data = read_whole(file.string());
    }
    return &(loaded_[i] = std::move(data));
  }

 private:
  const std::string& path_;
  const GltfFile& file_;
  const Json& doc_;
  std::map<size_t, std::string> loaded_;
};

// Reads the integers of index accessors; anything it cannot reach (an external buffer that is
// missing, a sparse accessor) is left to assimp, which says so in its own words.
class IndexChecker {
 public:
  explicit IndexChecker(GltfDocument& doc) : doc_(doc) {}

  void check() {
    const Json& meshes = doc_.member("meshes");
    for (size_t m = 0; m < meshes.size(); ++m) {
      const Json& prims = meshes[m].value("primitives", Json::array());
      for (size_t p = 0; p < prims.size(); ++p) check_primitive(prims[p], m, p);
    }
  }

 private:
  void check_primitive(const Json& prim, size_t m, size_t p) {
    if (!prim.is_object() || prim.value("mode", 4) != 4 || !prim.contains("indices")) return;
    const Json* attributes = prim.contains("attributes") ? &prim["attributes"] : nullptr;
    if (!attributes || !attributes->contains("POSITION")) return;
    const Json* position = doc_.element("accessors", (*attributes)["POSITION"]);
    const Json* indices = doc_.element("accessors", prim["indices"]);
    if (!position || !indices || indices->contains("sparse")) return;
    uint64_t vertices = position->value("count", uint64_t(0));
    const Json* view = doc_.element("bufferViews", indices->value("bufferView", Json()));
    if (!view) return;
    const std::string* data = doc_.buffer(view->value("buffer", size_t(0)));
    int size = indices->value("componentType", 0) == 5121   ? 1
               : indices->value("componentType", 0) == 5123 ? 2
               : indices->value("componentType", 0) == 5125 ? 4
                                                            : 0;
    if (!data || size == 0) return;
    uint64_t start =
        view->value("byteOffset", uint64_t(0)) + indices->value("byteOffset", uint64_t(0));
    uint64_t count = indices->value("count", uint64_t(0));
    if (start + count * size > data->size()) return;
    for (uint64_t k = 0; k < count; ++k) {
      uint32_t index = 0;
      std::memcpy(&index, data->data() + start + k * size, size);
      if (index < vertices) continue;
      throw_input_error(
          doc_.path(), fmt::format("meshes[{}].primitives[{}]", m, p),
          fmt::format("index {} of accessor {} is {}, beyond the {} vertices of its POSITION "
                      "accessor",
                      k, prim["indices"].get<size_t>(), index, vertices));
    }
  }

  GltfDocument& doc_;
};

constexpr int kFloat = 5126, kByte = 5120, kShort = 5122;

// An instance attribute of EXT_mesh_gpu_instancing: its accessor type and whether it may hold
// normalized BYTE or SHORT components besides FLOAT (the extension allows them for ROTATION).
struct InstanceAttribute {
  const char* name;
  const char* type;
  int components;
  bool normalized_integers;
};
constexpr InstanceAttribute kTranslation{"TRANSLATION", "VEC3", 3, false};
constexpr InstanceAttribute kRotation{"ROTATION", "VEC4", 4, true};
constexpr InstanceAttribute kScale{"SCALE", "VEC3", 3, false};

int component_bytes(int component_type) {
  return component_type == kFloat ? 4 : component_type == kShort ? 2 : 1;
}

// A component as a float; normalized integers as glTF maps them to [-1, 1].
float component_value(const char* p, int component_type) {
  if (component_type == kFloat) {
    float f;
    std::memcpy(&f, p, 4);
    return f;
  }
  if (component_type == kByte) return std::max(float(int8_t(*p)) / 127.0f, -1.0f);
  int16_t v;
  std::memcpy(&v, p, 2);
  return std::max(float(v) / 32767.0f, -1.0f);
}

std::string format_values(const float* v, int n) {
  std::string text;
  for (int i = 0; i < n; ++i) text += (i ? ", " : "") + fmt::format("{}", v[i]);
  return "(" + text + ")";
}

// The rotation of a glTF quaternion (x, y, z, w), normalized first: quantized ones are only
// close to unit length.
glm::mat3 rotation_matrix(const float* q) {
  return glm::mat3_cast(glm::normalize(glm::quat(q[3], q[0], q[1], q[2])));
}

// EXT_mesh_gpu_instancing, which assimp 5.2 ignores: the instances of a node's mesh, one per
// element of its attributes' accessors.
class GpuInstanceReader {
 public:
  explicit GpuInstanceReader(GltfDocument& doc) : doc_(doc) {}

  // The node's instances; none if it has no EXT_mesh_gpu_instancing.
  std::optional<std::vector<Transform>> read(const Json& node, size_t node_index) {
    auto extensions = node.find("extensions");
    if (extensions == node.end() || !extensions->is_object()) return std::nullopt;
    auto extension = extensions->find("EXT_mesh_gpu_instancing");
    if (extension == extensions->end()) return std::nullopt;
    node_ = node_index;
    const Json& attributes = attributes_of(*extension);
    uint64_t count = instance_count(attributes);
    // An accessor without a bufferView is zeros, so a tiny file can ask for billions.
    placed_ += count;
    require_memory(placed_ * kBytesPerInstance, doc_.path(),
                   fmt::format("{} EXT_mesh_gpu_instancing instances", placed_),
                   "place fewer instances");
    std::vector<float> translation = read_attribute(attributes, kTranslation, count);
    std::vector<float> rotation = read_attribute(attributes, kRotation, count);
    std::vector<float> scale = read_attribute(attributes, kScale, count);
    std::vector<Transform> instances(count);
    for (uint64_t k = 0; k < count; ++k) {
      Transform& t = instances[k];
      if (!rotation.empty()) t.linear = rotation_matrix(&rotation[4 * k]);
      for (int axis = 0; axis < 3 && !scale.empty(); ++axis) t.linear[axis] *= scale[3 * k + axis];
      if (!translation.empty()) t.offset = glm::make_vec3(&translation[3 * k]);
    }
    return instances;
  }

 private:
  std::string place(const std::string& attribute = "") const {
    return fmt::format("node {} EXT_mesh_gpu_instancing{}", node_,
                       attribute.empty() ? "" : " " + attribute);
  }

  [[noreturn]] void fail(const std::string& attribute, const std::string& what) const {
    throw_input_error(doc_.path(), place(attribute), what);
  }

  const Json& attributes_of(const Json& extension) const {
    auto attributes = extension.is_object() ? extension.find("attributes") : extension.end();
    if (attributes == extension.end() || !attributes->is_object() || attributes->empty())
      fail("", "has no attributes, so no instances");
    return *attributes;
  }

  const Json& accessor(const Json& attributes, const std::string& name) const {
    const Json* a = doc_.element("accessors", attributes[name]);
    if (!a || !a->is_object())
      fail(name, fmt::format("accessor {} does not exist (the file has {})",
                             attributes[name].dump(), doc_.member("accessors").size()));
    return *a;
  }

  // The count every attribute's accessor has (custom "_" ones included, as the extension asks).
  uint64_t instance_count(const Json& attributes) const {
    std::string first;
    uint64_t count = 0;
    for (const auto& item : attributes.items()) {
      const std::string& name = item.key();
      uint64_t n = whole(accessor(attributes, name), "count", name);
      if (first.empty()) {
        first = name;
        count = n;
      } else if (n != count) {
        fail(name, fmt::format("accessor {} has {} elements, {}'s accessor {} has {}: every "
                               "attribute needs one per instance",
                               item.value().dump(), n, first, attributes[first].dump(), count));
      }
    }
    if (count > std::numeric_limits<uint32_t>::max())
      fail(first,
           fmt::format("{} instances: more than rtsim's 32-bit instance ids can name", count));
    return count;
  }

  // object[key] as a whole number; `fallback` if absent.
  uint64_t whole(const Json& object, const char* key, const std::string& attribute,
                 uint64_t fallback = 0) const {
    auto it = object.find(key);
    if (it == object.end()) return fallback;
    if (!it->is_number_unsigned())
      fail(attribute, fmt::format("{} {} is not a whole number", key, it->dump()));
    return it->get<uint64_t>();
  }

  void check_format(const Json& a, const InstanceAttribute& attribute, size_t index) const {
    std::string type = a.value("type", "");
    if (type != attribute.type)
      fail(attribute.name,
           fmt::format("accessor {} is {}; it must be {}", index, type, attribute.type));
    int component_type = a.value("componentType", 0);
    bool integer = component_type == kByte || component_type == kShort;
    if (component_type != kFloat && !(integer && attribute.normalized_integers))
      fail(attribute.name,
           fmt::format(
               "accessor {} has componentType {}; it must be FLOAT (5126){}", index, component_type,
               attribute.normalized_integers ? ", or normalized BYTE (5120) or SHORT (5122)" : ""));
    if (integer && !a.value("normalized", false))
      fail(attribute.name, fmt::format("accessor {} has integer components that are not "
                                       "normalized",
                                       index));
    if (a.contains("sparse"))
      fail(attribute.name, fmt::format("accessor {} is sparse; rtsim reads instances from plain "
                                       "accessors only",
                                       index));
  }

  // Where the accessor's elements lie: the first one's bytes and the stride; nullptr for an
  // accessor without a bufferView, which glTF fills with zeros.
  std::pair<const char*, uint64_t> elements(const Json& a, size_t index, uint64_t element_bytes,
                                            const char* attribute) {
    uint64_t count = whole(a, "count", attribute);
    if (!a.contains("bufferView") || count == 0) return {nullptr, 0};
    const Json* view = doc_.element("bufferViews", a["bufferView"]);
    if (!view || !view->is_object())
      fail(attribute, fmt::format("accessor {}'s bufferView {} does not exist", index,
                                  a["bufferView"].dump()));
    uint64_t buffer_index = whole(*view, "buffer", attribute);
    const std::string* data = doc_.buffer(buffer_index);
    if (!data)
      fail(attribute, fmt::format("buffer {} of accessor {} cannot be read", buffer_index, index));
    uint64_t stride = whole(*view, "byteStride", attribute, element_bytes);
    uint64_t view_start = whole(*view, "byteOffset", attribute);
    uint64_t view_bytes = whole(*view, "byteLength", attribute);
    uint64_t start = whole(a, "byteOffset", attribute);
    if (stride < element_bytes)
      fail(attribute, fmt::format("bufferView {}'s byteStride {} is shorter than the {} bytes of "
                                  "accessor {}'s elements",
                                  a["bufferView"].dump(), stride, element_bytes, index));
    if (view_start > data->size() || view_bytes > data->size() - view_start || start > view_bytes ||
        element_bytes > view_bytes - start ||
        (count - 1) > (view_bytes - start - element_bytes) / stride)
      fail(attribute, fmt::format("the {} elements of accessor {} run past the end of its "
                                  "bufferView or buffer",
                                  count, index));
    return {data->data() + view_start + start, stride};
  }

  // The attribute's values, count x components floats, each checked to be finite; empty if the
  // node does not give the attribute.
  std::vector<float> read_attribute(const Json& attributes, const InstanceAttribute& attribute,
                                    uint64_t count) {
    if (!attributes.contains(attribute.name)) return {};
    const Json& a = accessor(attributes, attribute.name);
    size_t index = attributes[attribute.name].get<size_t>();
    check_format(a, attribute, index);
    int component_type = a.value("componentType", 0);
    int bytes = component_bytes(component_type);
    auto [first, stride] =
        elements(a, index, uint64_t(bytes) * attribute.components, attribute.name);
    std::vector<float> values(count * attribute.components, 0.0f);
    for (uint64_t k = 0; first && k < count; ++k)
      for (int c = 0; c < attribute.components; ++c)
        values[k * attribute.components + c] =
            component_value(first + k * stride + c * bytes, component_type);
    check_values(values, attribute);
    return values;
  }

  void check_values(const std::vector<float>& values, const InstanceAttribute& attribute) const {
    for (size_t k = 0; k * attribute.components < values.size(); ++k) {
      const float* v = &values[k * attribute.components];
      bool finite =
          std::all_of(v, v + attribute.components, [](float x) { return std::isfinite(x); });
      if (!finite)
        fail(attribute.name, fmt::format("instance {} is {}: NaN or Inf", k,
                                         format_values(v, attribute.components)));
      bool zero = std::all_of(v, v + attribute.components, [](float x) { return x == 0.0f; });
      if (zero && &attribute == &kRotation)
        fail(attribute.name, fmt::format("instance {} is (0, 0, 0, 0), not a rotation", k));
    }
  }

  // The instances' transforms here and in assimp's terms, their instance records and Embree's
  // instances, rounded up.
  static constexpr uint64_t kBytesPerInstance = 320;

  GltfDocument& doc_;
  size_t node_ = 0;
  uint64_t placed_ = 0;  // instances of the nodes read so far
};

// The unsigned entries of array `key` of object (assimp skips the others).
std::vector<size_t> node_indices(const Json& object, const char* key) {
  std::vector<size_t> indices;
  auto array = object.is_object() ? object.find(key) : object.end();
  if (array == object.end() || !array->is_array()) return indices;
  for (const Json& i : *array)
    if (i.is_number_unsigned()) indices.push_back(i.get<size_t>());
  return indices;
}

// assimp reads the node tree recursively (and so does SceneWalk), so a deep chain of nodes
// would overflow the stack; scenes nest a few dozen levels.
constexpr size_t kMaxNodeDepth = 1000;

constexpr size_t kNoParent = SIZE_MAX;

// Each node's parent, checking that every child exists and has no other parent, and that no node
// lists a child twice (glTF: "the node hierarchy MUST be a set of disjoint strict trees").
// assimp would place a node once per path to it: 2^40 times for 40 nodes that each list the next
// twice.
std::vector<size_t> node_parents(const std::string& path, const GltfNodeTree& tree) {
  std::vector<size_t> parent(tree.nodes.size(), kNoParent);
  for (size_t n = 0; n < tree.nodes.size(); ++n)
    for (size_t child : tree.nodes[n].children) {
      std::string place = fmt::format("node {}", n);
      if (child >= tree.nodes.size())
        throw_input_error(path, place,
                          fmt::format("child {} does not exist (the file has {} nodes)", child,
                                      tree.nodes.size()));
      if (parent[child] == n)
        throw_input_error(
            path, place,
            fmt::format("lists child {} twice; glTF node hierarchies are trees", child));
      if (parent[child] != kNoParent)
        throw_input_error(path, fmt::format("node {}", child),
                          fmt::format("has two parents, nodes {} and {}; glTF node hierarchies "
                                      "are trees",
                                      parent[child], n));
      parent[child] = n;
    }
  return parent;
}

// No node is its own ancestor, and none lies deeper than kMaxNodeDepth.
void check_node_depths(const std::string& path, const std::vector<size_t>& parent) {
  std::vector<size_t> depth(parent.size(), 0);                // 1: a root; 0: not known yet
  std::vector<size_t> walked_from(parent.size(), kNoParent);  // the walk that passed the node
  std::vector<size_t> chain;  // the walk's nodes of unknown depth, child first
  for (size_t n = 0; n < parent.size(); ++n) {
    chain.clear();
    size_t up = n;
    for (; up != kNoParent && depth[up] == 0; up = parent[up]) {
      if (walked_from[up] == n)
        throw_input_error(path, fmt::format("node {}", up),
                          "is its own ancestor (its children lead back to it); glTF node "
                          "hierarchies are trees");
      walked_from[up] = n;
      chain.push_back(up);
    }
    size_t below = up == kNoParent ? 0 : depth[up];
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) depth[*it] = ++below;
    if (below > kMaxNodeDepth)
      throw_input_error(path, fmt::format("node {}", n),
                        fmt::format("lies {} levels deep; rtsim reads node trees up to {} levels",
                                    below, kMaxNodeDepth));
  }
}

// A scene lists root nodes, each once.
void check_scene_roots(const std::string& path, const std::vector<size_t>& roots, size_t scene,
                       const std::vector<size_t>& parent) {
  std::vector<bool> listed(parent.size(), false);
  std::string place = fmt::format("scenes[{}]", scene);
  for (size_t root : roots) {
    if (root >= parent.size())
      throw_input_error(
          path, place,
          fmt::format("node {} does not exist (the file has {} nodes)", root, parent.size()));
    if (parent[root] != kNoParent)
      throw_input_error(
          path, place,
          fmt::format("lists node {}, a child of node {}, as a root node", root, parent[root]));
    if (listed[root]) throw_input_error(path, place, fmt::format("lists node {} twice", root));
    listed[root] = true;
  }
}

GltfNodeTree read_node_tree(GltfDocument& doc, const Json& json) {
  GltfNodeTree tree;
  const Json& nodes = doc.member("nodes");
  for (size_t n = 0; n < nodes.size(); ++n)
    tree.nodes.emplace_back().children = node_indices(nodes[n], "children");
  std::vector<size_t> parent = node_parents(doc.path(), tree);
  check_node_depths(doc.path(), parent);
  const Json& scenes = doc.member("scenes");
  for (size_t s = 0; s < scenes.size(); ++s)
    check_scene_roots(doc.path(), node_indices(scenes[s], "nodes"), s, parent);
  const Json scene = json.value("scene", Json(0));
  size_t shown = scene.is_number_unsigned() ? scene.get<size_t>() : 0;
  if (shown < scenes.size()) tree.roots = node_indices(scenes[shown], "nodes");
  GpuInstanceReader instances(doc);
  for (size_t n = 0; n < nodes.size(); ++n)
    if (nodes[n].is_object()) tree.nodes[n].gpu_instances = instances.read(nodes[n], n);
  return tree;
}

// glTF 1.0 is refused, naming the version: assimp would read it with another importer, silently
// without its materials. A document says so by asset.version ("1.0", "1.0.2"), or, unversioned,
// by collections that are JSON objects keyed by id where glTF 2.0 has arrays.
const char* const kGltf2Only = "rtsim reads glTF 2.0 (re-export the file as glTF 2.0)";

const Json* asset_version(const Json& json) {
  auto asset = json.find("asset");
  if (asset == json.end() || !asset->is_object()) return nullptr;
  auto version = asset->find("version");
  return version != asset->end() && version->is_string() ? &*version : nullptr;
}

void check_version(const std::string& path, const Json& json) {
  if (const Json* version = asset_version(json)) {
    std::string v = version->get<std::string>();
    if (v.rfind("2", 0) != 0)
      throw_input_error(
          path, "asset.version",
          fmt::format("'{}': glTF {}; {}", v, v.rfind("1", 0) == 0 ? "1.0" : v, kGltf2Only));
    return;
  }
  for (const char* key : {"meshes", "nodes", "accessors"}) {
    auto it = json.find(key);
    if (it != json.end() && it->is_object())
      throw_input_error(path, key,
                        fmt::format("an object keyed by id, as in glTF 1.0 (glTF 2.0 has an "
                                    "array), and no asset.version; {}",
                                    kGltf2Only));
  }
}

}  // namespace

bool GltfNodeTree::has_gpu_instances() const {
  return std::any_of(nodes.begin(), nodes.end(),
                     [](const GltfNode& n) { return n.gpu_instances.has_value(); });
}

GltfNodeTree check_gltf(const std::string& path, bool glb) {
  GltfFile file = read_container(path, glb);
  Json json = parse_document(path, file);
  if (!json.is_object()) return {};
  check_version(path, json);
  GltfDocument doc(path, file, json);
  try {
    IndexChecker(doc).check();
    GltfNodeTree tree = read_node_tree(doc, json);
    // Checked last, so that a broken document names what is broken: assimp reads no glTF
    // without a version ("No suitable reader found").
    if (!asset_version(json))
      throw_input_error(
          path, "asset.version",
          std::string("missing; glTF 2.0 names its version there, and ") + kGltf2Only);
    return tree;
  } catch (const Json::type_error& e) {  // a member of the wrong JSON type
    throw_input_error(path, "", std::string("malformed glTF: ") + e.what());
  }
}

}  // namespace rtsim
