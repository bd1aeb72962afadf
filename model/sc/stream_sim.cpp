#include "model/sc/stream_sim.h"

#include <fmt/core.h>

#include "traces/memory_plan.h"

namespace rtsim {

uint64_t rays_of(const StreamHeader& header, RayTypeMask types) {
  uint64_t n = 0;
  for (int t = 0; t < kRayTypeCount; ++t)
    if (types & ray_type_bit(RayType(t))) n += header.counts[size_t(t)];
  return n;
}

StreamSim::StreamSim(const HwConfig& config, BvhView bvh, const TriangleMesh& mesh,
                     const InstancedMesh& instances, RayStreamReader& reader, bool verify,
                     bool progress, RayTypeMask types)
    : source_(reader, types), progress_(progress ? rays_of(reader.header(), types) : 0) {
  if (progress) listeners_.add(&progress_);
  if (verify) {
    model_ = std::make_unique<TraversalUnit>(bvh);
    verifier_ = std::make_unique<SimVerifier>(
        make_verifier(*model_, mesh, instances, reader.header().instances));
    listeners_.add(verifier_.get());
  }
  const StreamHeader& header = reader.header();
  require_memory(header.pixels() * kPixelBufferBytes, reader.path(),
                 fmt::format("per-pixel buffers of its {} x {} grid", header.width, header.height),
                 "trace it at a lower resolution");
  sim_ =
      std::make_unique<RtSimulator>(config, bvh, source_, header.width, header.height, &listeners_);
}

void StreamSim::run() {
  try {
    sim_->run();
  } catch (...) {
    progress_.finish();
    throw;
  }
  progress_.finish();
}

}  // namespace rtsim
