// Checks every retired ray of the timing model against Embree (robust mode): the answer the
// timed traversal state holds is compared with EmbreeScene::trace, and every disagreement
// goes to the double-precision arbiter, exactly as `rtsim verify` does (model/verify). The
// count that must stay zero is report().unexplained().
#pragma once

#include "model/sched/ray_supply.h"
#include "model/verify/verifier.h"

namespace rtsim {

class SimVerifier : public RayRetireListener {
public:
  SimVerifier(const TriangleMesh& mesh, const TraversalUnit& model, const EmbreeScene& embree,
              ArbiterConfig config = {}, size_t max_examples = 10);
  void retired(const RayContext& ray, Cycle now) override;
  const VerifyReport& report() const { return report_; }

private:
  const TraversalUnit& model_;
  const EmbreeScene& embree_;
  Arbiter arbiter_;
  size_t max_examples_;
  VerifyReport report_;
};

}  // namespace rtsim
