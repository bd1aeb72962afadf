// Checks the model against Embree ray by ray: the traversal unit and EmbreeScene (robust mode)
// trace the same ray; hit or miss, triangle and t (within tolerance) must agree, and every
// disagreement goes to the double-precision arbiter. This is what `rtsim verify` runs and what
// the timing model will run beside every timed ray.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "model/units/traversal.h"
#include "model/verify/arbiter.h"
#include "traces/embree_scene.h"

namespace rtsim {

struct Mismatch {
  uint64_t index = 0;  // ray number in the stream
  Ray ray;
  Hit embree, model;
  uint32_t model_prim = kNoHit;  // the triangle the model hit, also for any-hit queries
  Verdict verdict;
};

struct VerifyReport {
  uint64_t rays = 0;
  uint64_t agree = 0;
  uint64_t model_hits = 0, embree_hits = 0;
  std::array<uint64_t, kMismatchClassCount> by_class{};
  std::array<std::array<uint64_t, kRightSideCount>, kMismatchClassCount> right{};
  std::array<uint64_t, kRayTypeCount> rays_by_type{}, mismatches_by_type{};
  TraversalCounters counters;  // summed over all rays
  uint64_t accesses = 0, access_bytes = 0;
  std::vector<Mismatch> examples;              // the first max_examples mismatches
  std::vector<Mismatch> unexplained_examples;  // the first max_examples unexplained ones

  uint64_t mismatches() const { return rays - agree; }
  uint64_t unexplained() const { return by_class[int(MismatchClass::Unexplained)]; }
};

class Verifier {
 public:
  // triangles: the scene by flat id; embree: the reference over the same scene, flat, or over
  // its instances for a two-level model. Hits that name an instance and a triangle of its mesh
  // (the two-level model's, Embree's instances') are compared and judged as flat ids.
  Verifier(FlatTriangles triangles, const TraversalUnit& model, const EmbreeScene& embree,
           ArbiterConfig config = {}, size_t max_examples = 10);

  // Traces one ray both ways and records the outcome; returns true if they agree.
  bool check(const Ray& ray);
  // Records the outcome of a ray the model has traced already (state: the model's traversal
  // state at its end; index: the ray's number in the stream); returns true if they agree.
  bool judge(const Ray& ray, const TraversalState& state, uint64_t index);
  const VerifyReport& report() const { return report_; }

 private:
  const TraversalUnit& model_;
  const EmbreeScene& embree_;
  Arbiter arbiter_;
  size_t max_examples_;
  TraversalState state_;
  VerifyReport report_;
};

// A verifier with the reference it checks against: Embree over the flat mesh, or for a
// two-level model (model.bvh().two_level()) over `instances`, whose flattening `flat` is (flat
// may be empty then: a scene that keeps no flattened copy) under the workload's instance
// settings (masks, motion), which it keeps a copy of.
struct VerifierSetup {
  std::unique_ptr<InstanceSettings> settings;
  std::unique_ptr<EmbreeScene> reference;
  std::unique_ptr<Verifier> verifier;
};
VerifierSetup make_verifier(const TraversalUnit& model, const TriangleMesh& flat,
                            const InstancedMesh& instances, const InstanceSettings& settings = {},
                            ArbiterConfig config = {}, size_t max_examples = 10);

}  // namespace rtsim
