#include "workloads/scene_file_check.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <string_view>

#include <fmt/format.h>

#include "traces/error.h"

namespace rtsim {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// The elements OBJ indices refer to, counted as they are defined.
struct ObjCounts {
  long long defined[3] = {0, 0, 0};  // positions (v), texture coordinates (vt), normals (vn)
};

const char* const kElement[3] = {"vertex", "texture coordinate", "normal"};
const char* const kElements[3] = {"vertices", "texture coordinates", "normals"};
const char* const kKeyword[3] = {"v", "vt", "vn"};

// One index of a face corner: "7", "-2" or "" (an omitted texture coordinate, as in "7//3").
void check_index(const std::string& path, size_t line, std::string_view text, int kind,
                 const ObjCounts& counts, std::string_view corner) {
  if (text.empty() && kind > 0) return;
  std::string digits(text);
  char* end = nullptr;
  long long index = std::strtoll(digits.c_str(), &end, 10);
  std::string place = fmt::format("line {}", line);
  if (digits.empty() || *end != '\0')
    throw_input_error(path, place,
                      fmt::format("'{}' is not an index of the form v, v/vt or v/vt/vn", corner));
  long long n = counts.defined[kind];
  if (index == 0)
    throw_input_error(
        path, place,
        fmt::format("{} index 0 in '{}': OBJ indices start at 1", kElement[kind], corner));
  if (index > n || -index > n)
    throw_input_error(path, place,
                      fmt::format("'{}' refers to {} {}, but only {} {} ('{}' lines) are defined "
                                  "above this line",
                                  corner, kElement[kind], index, n,
                                  n == 1 ? kElement[kind] : kElements[kind], kKeyword[kind]));
}

void check_corner(const std::string& path, size_t line, std::string_view corner,
                  const ObjCounts& counts) {
  int kind = 0;
  size_t start = 0;
  for (size_t slash = corner.find('/'); kind < 3; slash = corner.find('/', start)) {
    std::string_view part =
        corner.substr(start, slash == std::string_view::npos ? slash : slash - start);
    check_index(path, line, part, kind, counts, corner);
    if (slash == std::string_view::npos) return;
    start = slash + 1;
    ++kind;
  }
  throw_input_error(path, fmt::format("line {}", line),
                    fmt::format("'{}' has more than three indices", corner));
}

}  // namespace

void check_obj_indices(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_input_error(path, "", "cannot open the scene file");
  ObjCounts counts;
  std::string text;
  for (size_t line = 1; std::getline(in, text); ++line) {
    std::string_view s = trim(text);
    size_t space = s.find_first_of(" \t");
    std::string_view keyword = s.substr(0, space);
    if (keyword == "v" || keyword == "vt" || keyword == "vn") {
      counts.defined[keyword == "v" ? 0 : keyword == "vt" ? 1 : 2]++;
      continue;
    }
    if (keyword != "f" && keyword != "l" && keyword != "p") continue;
    std::string_view rest = space == std::string_view::npos ? "" : s.substr(space);
    while (!(rest = trim(rest)).empty()) {
      size_t end = rest.find_first_of(" \t");
      if (rest[0] == '#')
        throw_input_error(path, fmt::format("line {}", line),
                          "a comment after the indices is not read (assimp rejects the line); "
                          "put it on a line of its own");
      check_corner(path, line, rest.substr(0, end), counts);
      rest = end == std::string_view::npos ? "" : rest.substr(end);
    }
  }
}

}  // namespace rtsim
