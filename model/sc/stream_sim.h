// The cycle model over a whole ray stream, as `rtsim sim` and `rtsim run` drive it: the machine
// fed from the stream, every retired ray told to the listeners, a progress bar if asked, and,
// with verify, every ray checked against Embree. One per process (SystemC elaborates once).
#pragma once

#include <memory>

#include "model/sc/rt_simulator.h"
#include "model/sc/sim_progress.h"
#include "model/sched/ray_source.h"
#include "model/sched/sim_stats.h"
#include "model/sched/sim_verifier.h"

namespace rtsim {

// The rays of the given types in a stream, by its header.
uint64_t rays_of(const StreamHeader& header, RayTypeMask types);

class StreamSim {
 public:
  // types: the ray types of the stream to simulate (the others are skipped).
  // mesh: the scene's world-space triangles; instances: its instance structure (what a
  // two-level bvh was built over), for verify.
  StreamSim(const HwConfig& config, BvhView bvh, const TriangleMesh& mesh,
            const InstancedMesh& instances, RayStreamReader& reader, bool verify, bool progress,
            RayTypeMask types = kAllRayTypes);
  // Tells the listener of every retired ray; call before run().
  void listen(RayRetireListener* listener) { listeners_.add(listener); }
  // Runs to the end of the stream; throws SimStallError if the machine stalls, InputError for
  // a bad stream.
  void run();
  const RtSimulator& simulator() const { return *sim_; }
  const VerifyReport* verify_report() const { return verifier_ ? &verifier_->report() : nullptr; }

 private:
  std::unique_ptr<TraversalUnit> model_;
  std::unique_ptr<SimVerifier> verifier_;
  StreamRaySource source_;
  SimProgress progress_;
  RetireFanout listeners_;
  std::unique_ptr<RtSimulator> sim_;
};

}  // namespace rtsim
