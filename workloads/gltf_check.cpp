// The glTF 2.0 checks of scene_file_check.h: the GLB container, the JSON document, and every
// triangle index against its primitive's POSITION count (assimp drops the faces of a primitive
// with an index out of range and then reports only that the mesh "has no faces").
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "traces/error.h"
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

Json parse_document(const std::string& path, const GltfFile& f) {
  try {
    return Json::parse(f.json);
  } catch (const Json::parse_error& e) {
    size_t byte = e.byte == 0 ? 0 : std::min<size_t>(e.byte - 1, f.json.size());
    size_t line = 1 + size_t(std::count(f.json.begin(), f.json.begin() + byte, '\n'));
    std::string what = e.what();
    size_t colon = what.find(": ", what.find("parse error"));
    std::string reason = colon == std::string::npos ? what : what.substr(colon + 2);
    throw_input_error(
        path,
        f.binary ? fmt::format("offset {}", f.json_offset + byte) : fmt::format("line {}", line),
        "not valid JSON: " + reason);
  }
}

// Reads the integers of index accessors; anything it cannot reach (an external buffer that is
// missing, a sparse accessor) is left to assimp, which says so in its own words.
class IndexChecker {
 public:
  IndexChecker(const std::string& path, const GltfFile& f, const Json& doc)
      : path_(path), file_(f), doc_(doc) {}

  void check() {
    const Json& meshes = member("meshes");
    for (size_t m = 0; m < meshes.size(); ++m) {
      const Json& prims = meshes[m].value("primitives", Json::array());
      for (size_t p = 0; p < prims.size(); ++p) check_primitive(prims[p], m, p);
    }
  }

 private:
  const Json& member(const char* key) const {
    static const Json kEmpty = Json::array();
    auto it = doc_.find(key);
    return it != doc_.end() && it->is_array() ? *it : kEmpty;
  }

  const Json* element(const char* array, const Json& index) const {
    const Json& a = member(array);
    if (!index.is_number_unsigned() || index.get<size_t>() >= a.size()) return nullptr;
    return &a[index.get<size_t>()];
  }

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

  void check_primitive(const Json& prim, size_t m, size_t p) {
    if (!prim.is_object() || prim.value("mode", 4) != 4 || !prim.contains("indices")) return;
    const Json* attributes = prim.contains("attributes") ? &prim["attributes"] : nullptr;
    if (!attributes || !attributes->contains("POSITION")) return;
    const Json* position = element("accessors", (*attributes)["POSITION"]);
    const Json* indices = element("accessors", prim["indices"]);
    if (!position || !indices || indices->contains("sparse")) return;
    uint64_t vertices = position->value("count", uint64_t(0));
    const Json* view = element("bufferViews", indices->value("bufferView", Json()));
    if (!view) return;
    const std::string* data = buffer(view->value("buffer", size_t(0)));
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
          path_, fmt::format("meshes[{}].primitives[{}]", m, p),
          fmt::format("index {} of accessor {} is {}, beyond the {} vertices of its POSITION "
                      "accessor",
                      k, prim["indices"].get<size_t>(), index, vertices));
    }
  }

  const std::string& path_;
  const GltfFile& file_;
  const Json& doc_;
  std::map<size_t, std::string> loaded_;
};

}  // namespace

void check_gltf(const std::string& path, bool glb) {
  GltfFile file = read_container(path, glb);
  Json doc = parse_document(path, file);
  if (doc.is_object()) IndexChecker(path, file, doc).check();
}

}  // namespace rtsim
