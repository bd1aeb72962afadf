// Sizes in bytes as people write them, read in one place for every config key, spec and option
// that takes one: a number of bytes, or a number with a binary suffix (4096, 4096B, 256K,
// 64KiB, 4M, 4MiB, 1G, 1GiB, 1T, 1TiB; K = KiB = 1,024 bytes, M = MiB, G = GiB, T = TiB).
// byte_size_text writes a size back the short way (256K, 1M, 4M), as chart axes label it.
#pragma once

#include <cstdint>
#include <string>

namespace rtsim {

// The bytes text names; throws InputError "PLACE: WHAT" for a bad number or suffix ("4x") or a
// size past 2^64-1 bytes. Range (zero included) is the caller's to check.
uint64_t parse_byte_size(const std::string& text, const std::string& place);

// Why text is not a size ("" if it is one); *bytes gets its value.
std::string byte_size_problem(const std::string& text, uint64_t* bytes);

// The largest binary unit that divides bytes: "256K", "1M", "4M", "1G"; "100" below a KiB or
// where no unit divides.
std::string byte_size_text(uint64_t bytes);

}  // namespace rtsim
