// Byte layouts of triangles in the simulated memory (tables in model/README.md):
//  - raw:  v0, v1, v2 as fp32 xyz, then the 32-bit primitive id: 40 bytes. The ray-triangle
//          unit runs the watertight test of Woop, Benthin & Wald (JCGT 2013) on it.
//  - woop: the precomputed affine map into the unit-triangle space of Woop, "Ray Tracing
//          Hardware Architecture" (2004), three fp32 rows of 4, then the id: 52 bytes. Cheaper
//          to test, not watertight, and imprecise far from the origin.
//  - amd_tri: AMD RDNA2/3's triangle node, radv_bvh_triangle_node (amd_nodes.h): the vertices,
//          the id at byte 48, opacity and barycentrics control: 64 bytes. Tested watertight, as
//          raw (AMD does not publish its unit's arithmetic).
#pragma once

#include <cstdint>

#include "model/bvh/bvh_config.h"
#include "traces/ray.h"

namespace rtsim {

constexpr uint32_t kRawTriangleBytes = 40;
constexpr uint32_t kWoopTriangleBytes = 52;

uint32_t triangle_stride(TriangleFormat format);

// Writes the record of triangle `prim` of the mesh.
void encode_triangle(TriangleFormat format, const TriangleMesh& mesh, uint32_t prim, uint8_t* out);

}  // namespace rtsim
