#include "model/sched/sim_verifier.h"

#include <cmath>

namespace rtsim {

SimVerifier::SimVerifier(const TriangleMesh& mesh, const TraversalUnit& model,
                         const EmbreeScene& embree, ArbiterConfig config, size_t max_examples)
    : model_(model), embree_(embree), arbiter_(mesh, embree, config), max_examples_(max_examples) {}

void SimVerifier::retired(const RayContext& context, Cycle) {
  const Ray& ray = context.ray;
  const TraversalState& state = context.state;
  Hit model = model_.result(state, ray);
  Hit embree = embree_.trace(ray);
  float model_t = std::ldexp(state.t_hit, state.ray.t_exponent);
  int type = static_cast<int>(ray.type);
  report_.rays++;
  report_.rays_by_type[type]++;
  report_.model_hits += model.hit();
  report_.embree_hits += embree.hit();
  report_.counters += state.counters;
  Verdict verdict = arbiter_.judge(ray, embree, state.prim, model_t);
  if (verdict.agree) {
    report_.agree++;
    return;
  }
  int cls = static_cast<int>(verdict.cls);
  report_.by_class[cls]++;
  report_.right[cls][static_cast<int>(verdict.right)]++;
  report_.mismatches_by_type[type]++;
  Mismatch example{context.sequence, ray, embree, model, state.prim, verdict};
  if (report_.examples.size() < max_examples_) report_.examples.push_back(example);
  if (verdict.cls == MismatchClass::Unexplained &&
      report_.unexplained_examples.size() < max_examples_)
    report_.unexplained_examples.push_back(example);
}

}  // namespace rtsim
