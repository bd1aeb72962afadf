#include "traces/path_name.h"

#include <fmt/core.h>

namespace rtsim {

std::string path_name_problem(const std::string& name) {
  if (name.empty()) return "the name is empty";
  if (name.size() > kMaxPathNameBytes)
    return fmt::format("the name is {} bytes, more than {}", name.size(), kMaxPathNameBytes);
  if (name[0] == '.') return fmt::format("'{}' starts with '.'", name);
  for (char c : name) {
    if (c == '/' || c == '\\') return fmt::format("'{}' holds a '{}'", name, c);
    if ((unsigned char)c < 0x20 || c == 0x7f) return "the name holds a control character";
  }
  return "";
}

}  // namespace rtsim
