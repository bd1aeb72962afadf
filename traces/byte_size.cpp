#include "traces/byte_size.h"

#include <cctype>
#include <utility>

#include <fmt/format.h>

#include "traces/error.h"

namespace rtsim {
namespace {

constexpr std::pair<const char*, int> kSuffixes[] = {{"", 0},   {"B", 0},    {"K", 10}, {"KiB", 10},
                                                     {"M", 20}, {"MiB", 20}, {"G", 30}, {"GiB", 30},
                                                     {"T", 40}, {"TiB", 40}};

constexpr const char* kForms = "bytes, or a number with K, M, G or T (KiB, MiB, GiB, TiB): 64K, 4M";

}  // namespace

std::string byte_size_problem(const std::string& text, uint64_t* bytes) {
  size_t end = 0;
  uint64_t value = 0;
  while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) {
    if (__builtin_mul_overflow(value, 10, &value) ||
        __builtin_add_overflow(value, uint64_t(text[end] - '0'), &value))
      return fmt::format("'{}' is more than 2^64-1 bytes", text);
    ++end;
  }
  if (end == 0) return fmt::format("'{}' is not a size ({})", text, kForms);
  std::string suffix = text.substr(end);
  for (const auto& [name, shift] : kSuffixes) {
    if (suffix != name) continue;
    if (shift && value > (UINT64_MAX >> shift))
      return fmt::format("'{}' is more than 2^64-1 bytes", text);
    *bytes = value << shift;
    return "";
  }
  return fmt::format("'{}': unknown suffix '{}' (a size is {})", text, suffix, kForms);
}

uint64_t parse_byte_size(const std::string& text, const std::string& place) {
  uint64_t bytes = 0;
  std::string problem = byte_size_problem(text, &bytes);
  if (!problem.empty()) throw_input_error(place, "", problem);
  return bytes;
}

std::string byte_size_text(uint64_t bytes) {
  for (const auto& [unit, shift] : {std::pair{"T", 40}, {"G", 30}, {"M", 20}, {"K", 10}})
    if (bytes != 0 && bytes % (uint64_t(1) << shift) == 0)
      return fmt::format("{}{}", bytes >> shift, unit);
  return std::to_string(bytes);
}

}  // namespace rtsim
