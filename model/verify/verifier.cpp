#include "model/verify/verifier.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace rtsim {

Verifier::Verifier(FlatTriangles triangles, const TraversalUnit& model, const EmbreeScene& embree,
                   ArbiterConfig config, size_t max_examples)
    : model_(model),
      embree_(embree),
      arbiter_(std::move(triangles), embree, config),
      max_examples_(max_examples) {}

bool Verifier::check(const Ray& ray) {
  model_.trace(state_, ray);
  return judge(ray, state_, report_.rays);
}

bool Verifier::judge(const Ray& ray, const TraversalState& state, uint64_t index) {
  Hit model = model_.result(state, ray);
  Hit embree = embree_.trace(ray);
  const FlatTriangles& triangles = arbiter_.triangles();
  model = triangles.flat(model);
  embree = triangles.flat(embree);
  uint32_t model_prim = triangles.flat_id(state.hit_instance, state.prim);
  float model_t = std::ldexp(state.t_hit, state.ray.t_exponent);
  int type = static_cast<int>(ray.type);
  report_.rays++;
  report_.rays_by_type[type]++;
  report_.model_hits += model.hit();
  report_.embree_hits += embree.hit();
  report_.counters += state.counters;
  report_.accesses += state.accesses.size();
  for (const MemoryAccess& a : state.accesses) report_.access_bytes += a.bytes;

  Verdict verdict = arbiter_.judge(ray, embree, model_prim, model_t);
  if (verdict.agree) {
    report_.agree++;
    return true;
  }
  int cls = static_cast<int>(verdict.cls);
  report_.by_class[cls]++;
  report_.right[cls][static_cast<int>(verdict.right)]++;
  report_.mismatches_by_type[type]++;
  Mismatch example{index, ray, embree, model, model_prim, verdict};
  if (report_.examples.size() < max_examples_) report_.examples.push_back(example);
  if (verdict.cls == MismatchClass::Unexplained &&
      report_.unexplained_examples.size() < max_examples_)
    report_.unexplained_examples.push_back(example);
  return false;
}

VerifierSetup make_verifier(const TraversalUnit& model, const TriangleMesh& flat,
                            const InstancedMesh& instances, const InstanceSettings& settings,
                            ArbiterConfig config, size_t max_examples) {
  VerifierSetup out;
  if (!model.bvh().two_level()) {
    out.reference = std::make_unique<EmbreeScene>(flat);
    out.verifier = std::make_unique<Verifier>(flat, model, *out.reference, config, max_examples);
    return out;
  }
  if (instances.instanced_triangles() >= kAnyPrim)
    throw std::invalid_argument("Verifier: more instanced triangles than 32-bit ids can name");
  out.settings = std::make_unique<InstanceSettings>(settings);
  out.reference = std::make_unique<EmbreeScene>(instances, settings);
  out.verifier = std::make_unique<Verifier>(FlatTriangles(instances, out.settings.get()), model,
                                            *out.reference, config, max_examples);
  return out;
}

}  // namespace rtsim
