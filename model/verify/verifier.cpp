#include "model/verify/verifier.h"

#include <cmath>

namespace rtsim {

Verifier::Verifier(const TriangleMesh& mesh, const TraversalUnit& model, const EmbreeScene& embree,
                   ArbiterConfig config, size_t max_examples)
    : model_(model), embree_(embree), arbiter_(mesh, embree, config), max_examples_(max_examples) {}

bool Verifier::check(const Ray& ray) {
  Hit model = model_.trace(state_, ray);
  Hit embree = embree_.trace(ray);
  uint32_t model_prim = state_.prim;
  float model_t = std::ldexp(state_.t_hit, state_.ray.t_exponent);
  int type = static_cast<int>(ray.type);
  report_.rays++;
  report_.rays_by_type[type]++;
  report_.model_hits += model.hit();
  report_.embree_hits += embree.hit();
  report_.counters += state_.counters;
  report_.accesses += state_.accesses.size();
  for (const MemoryAccess& a : state_.accesses) report_.access_bytes += a.bytes;

  Verdict verdict = arbiter_.judge(ray, embree, model_prim, model_t);
  if (verdict.agree) {
    report_.agree++;
    return true;
  }
  int cls = static_cast<int>(verdict.cls);
  report_.by_class[cls]++;
  report_.right[cls][static_cast<int>(verdict.right)]++;
  report_.mismatches_by_type[type]++;
  Mismatch example{report_.rays - 1, ray, embree, model, model_prim, verdict};
  if (report_.examples.size() < max_examples_) report_.examples.push_back(example);
  if (verdict.cls == MismatchClass::Unexplained &&
      report_.unexplained_examples.size() < max_examples_)
    report_.unexplained_examples.push_back(example);
  return false;
}

}  // namespace rtsim
