#include "model/sc/stream_sim.h"

namespace rtsim {

StreamSim::StreamSim(const HwConfig& config, const BvhImage& image, const TriangleMesh& mesh,
                     RayStreamReader& reader, bool verify, bool progress)
    : source_(reader), progress_(progress ? reader.header().total_rays() : 0) {
  if (progress) listeners_.add(&progress_);
  if (verify) {
    embree_ = std::make_unique<EmbreeScene>(mesh);
    model_ = std::make_unique<TraversalUnit>(image);
    verifier_ = std::make_unique<SimVerifier>(mesh, *model_, *embree_);
    listeners_.add(verifier_.get());
  }
  const StreamHeader& header = reader.header();
  sim_ = std::make_unique<RtSimulator>(config, image, source_, header.width, header.height,
                                       &listeners_);
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
