// Checksums and fingerprints shared by the ray-stream format and scenes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace rtsim {

// CRC-32 (IEEE 802.3 polynomial, as zlib): detects every single-byte and burst error <= 32 bits.
uint32_t crc32(const void* data, size_t size, uint32_t crc = 0);

// 64-bit FNV-1a over bytes, chainable; used for scene fingerprints.
uint64_t fnv1a64(const void* data, size_t size, uint64_t hash = 0xcbf29ce484222325ull);

// 16 lowercase hex digits, as hashes and fingerprints are written.
std::string hex64(uint64_t value);

// hex64 of the text's fnv1a64: the content keys of specs, sweep points and suite traces.
std::string text_hash(std::string_view text);

}  // namespace rtsim
