// Dispatch of the built-in scene names and the parsing of their parameter.
#include <charconv>

#include <fmt/core.h>

#include "traces/error.h"
#include "traces/memory_plan.h"
#include "workloads/builtin_scenes.h"
#include "workloads/hardcases.h"

namespace rtsim::builtin {

uint64_t parse_triangle_count(const std::string& source, const std::string& text) {
  uint64_t n = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, n);
  if (text.empty() || ec != std::errc() || ptr != end || n == 0 || n > kMaxBuiltinTriangles)
    throw_input_error(source, "",
                      "the triangle count must be a whole number from 1 to " +
                          std::to_string(kMaxBuiltinTriangles) + ", got '" + text + "'");
  return n;
}

Scene make_builtin_scene(const std::string& name_and_params) {
  const std::string source = "builtin:" + name_and_params;
  if (name_and_params == "cornell") return make_cornell();
  if (name_and_params == "pica") return make_pica();
  if (name_and_params == "hardcases") return hardcases::make_hardcases_scene();
  auto colon = name_and_params.find(':');
  std::string name = name_and_params.substr(0, colon);
  if (name == "grid" || name == "foliage" || name == "forest" || name == "city") {
    if (colon == std::string::npos)
      throw_input_error(source, "", "needs a triangle count, as in '" + name + ":100000'");
    uint64_t n = parse_triangle_count(source, name_and_params.substr(colon + 1));
    std::string canonical = "builtin:" + name + ":" + std::to_string(n);
    // A forest or a city holds its few unique meshes and the instances placing them, whatever N.
    if (name == "forest") return make_forest(canonical, n);
    if (name == "city") return make_city(canonical, n);
    // Measured: 26 B a triangle at the peak of scene-info grid:4000000 (positions, indices,
    // materials and the fingerprint pass).
    require_memory(n * 28, source, fmt::format("a scene of {} triangles", n),
                   "ask for fewer triangles");
    return name == "grid" ? make_grid(canonical, n) : make_foliage(canonical, n);
  }
  std::string known;
  for (const auto& s : builtin_scene_names()) known += (known.empty() ? "" : ", ") + s;
  throw_input_error(source, "", "unknown built-in scene; the built-ins are " + known);
}

}  // namespace rtsim::builtin
