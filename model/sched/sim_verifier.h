// Checks every retired ray of the timing model against Embree (robust mode): the answer the
// timed traversal state holds is judged as `rtsim verify` judges it (model/verify), every
// disagreement by the double-precision arbiter. The count that must stay zero is
// report().unexplained().
#pragma once

#include <utility>

#include "model/sched/ray_supply.h"
#include "model/verify/verifier.h"

namespace rtsim {

class SimVerifier : public RayRetireListener {
 public:
  // checks: made over the traversal unit the timing model drives (one or two levels).
  explicit SimVerifier(VerifierSetup checks) : checks_(std::move(checks)) {}
  void retired(const RayContext& ray, Cycle) override {
    checks_.verifier->judge(ray.ray, ray.state, ray.sequence);
  }
  const VerifyReport& report() const { return checks_.verifier->report(); }

 private:
  VerifierSetup checks_;
};

}  // namespace rtsim
