// Device tracing times from the cycle-approximate model: each task is one RtSimulator run of
// the device's hardware config over its rays, in a forked child (SystemC elaborates once per
// process), up to `jobs` children at a time. A BVH (one level or two, bvh.instancing) is built
// once per distinct BVH config.
// Results are deterministic: they do not depend on jobs or on the order children finish.
#pragma once

#include <map>
#include <string>

#include "model/bvh/two_level.h"
#include "model/multi/device_backend.h"

namespace rtsim::multi {

class SystemCBackend : public DeviceBackend {
 public:
  // mesh: the scene's world-space triangles (empty for a scene kept as instances only);
  // instances: its instance structure.
  // settings: the stream's instance masks and motion (traces/instance_settings.h).
  SystemCBackend(const TriangleMesh& mesh, const InstancedMesh& instances,
                 const InstanceSettings& settings, unsigned jobs);
  std::vector<DeviceResult> run(const std::vector<DeviceTask>& tasks,
                                const ScreenLayout& layout) override;

 private:
  const TwoLevelBvh& bvh_for(const HwConfig& config);

  const TriangleMesh& mesh_;
  TriangleMesh flattened_;  // made from instances_ when mesh_ is empty and needed
  InstancedMesh instances_;
  InstanceSettings settings_;
  unsigned jobs_;
  std::map<std::string, TwoLevelBvh> bvhs_;  // by resolved BVH config
};

}  // namespace rtsim::multi
