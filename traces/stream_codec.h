// Byte layout of the .rays header and ray records (see traces/FORMAT.md); internal to traces/.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "traces/bytes.h"
#include "traces/stream.h"

namespace rtsim {

constexpr char kStreamMagic[8] = {'R', 'T', 'S', 'I', 'M', 'R', 'A', 'Y'};
constexpr size_t kHeaderFixedBytes = 112;       // magic .. counts, before the strings
constexpr uint32_t kMaxHeaderBytes = 1u << 26;  // instance settings make it grow

// The whole header including its trailing CRC.
std::vector<uint8_t> encode_header(const StreamHeader& header);
// The instance settings section (version 2), after the strings.
void encode_instance_settings(const InstanceSettings& settings, std::vector<uint8_t>& out);
// Reads the section; false if it does not fit the bytes left.
bool decode_instance_settings(ByteReader& in, InstanceSettings& settings);
void encode_ray(const Ray& ray, std::vector<uint8_t>& out);
Ray decode_ray(const uint8_t* record);

}  // namespace rtsim
