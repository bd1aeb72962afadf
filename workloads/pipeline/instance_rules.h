// A spec's [[instances]] rules and [ray_masks] resolved against a scene's instances, by object
// name: the InstanceSettings the trace applies and its stream records.
#pragma once

#include "traces/instance_settings.h"
#include "workloads/pipeline/spec.h"
#include "workloads/scene.h"

namespace rtsim::pipeline {

// The scene is kept as instances (keep_as_instances). Later rules win, for the mask and the
// motion each. InputError naming the spec and the rule's
// line for a rule that matches no instance. Empty settings for a spec without rules or masks.
InstanceSettings resolve_instance_rules(const WorkloadSpec& spec, const Scene& scene);

}  // namespace rtsim::pipeline
