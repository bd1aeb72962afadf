#include "workloads/pipeline/instance_rules.h"

#include <fmt/core.h>

#include "traces/error.h"
#include "workloads/pipeline/materials.h"

namespace rtsim::pipeline {

InstanceSettings resolve_instance_rules(const WorkloadSpec& spec, const Scene& scene) {
  InstanceSettings out;
  out.ray_masks = spec.ray_masks;
  out.frames = spec.frames;
  if (spec.instances.empty()) return out;
  const std::vector<Instance>& instances = scene.instanced.instances;
  const std::vector<uint32_t>& objects = scene.instance_object_ids;
  std::vector<int> mask_rule(instances.size(), -1), motion_rule(instances.size(), -1);
  for (size_t r = 0; r < spec.instances.size(); ++r) {  // the scene: kept as instances
    const InstanceRule& rule = spec.instances[r];
    bool matched = false;
    for (size_t i = 0; i < instances.size(); ++i) {
      if (!glob_match(rule.match, scene.object_names[objects[i]])) continue;
      matched = true;
      if (rule.mask) mask_rule[i] = int(r);
      if (!rule.motion.keys.empty()) motion_rule[i] = int(r);
    }
    if (!matched)
      throw_input_error(spec.file.empty() ? spec.name : spec.file, rule.where,
                        fmt::format("instance rule '{}' matches no instance's object name in {} "
                                    "({} instances)",
                                    rule.match, scene.source, instances.size()));
  }
  std::vector<int> motion_of_rule(spec.instances.size(), -1);
  for (uint32_t i = 0; i < instances.size(); ++i) {
    if (mask_rule[i] >= 0) out.masks.push_back({i, *spec.instances[size_t(mask_rule[i])].mask});
    if (motion_rule[i] < 0) continue;
    int& motion = motion_of_rule[size_t(motion_rule[i])];
    if (motion < 0) {
      motion = int(out.motions.size());
      out.motions.push_back(spec.instances[size_t(motion_rule[i])].motion);
    }
    out.moving.push_back({i, uint32_t(motion)});
  }
  return out;
}

}  // namespace rtsim::pipeline
