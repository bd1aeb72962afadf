#include "model/multi/systemc_backend.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <numeric>
#include <stdexcept>

#include "model/sc/fork_run.h"
#include "model/multi/slot_cost.h"
#include "model/sc/rt_simulator.h"
#include "model/sched/ray_source.h"

namespace rtsim::multi {
namespace {

// Child to parent, in this machine's byte order: rays and cycles (u64 each), rays and cycles
// per ray type (f64 each), then one float per position of the region.
constexpr size_t kHeaderBytes = 16 + 2 * kRayTypeCount * sizeof(double);

std::string encode(const DeviceResult& r) {
  std::string bytes(kHeaderBytes + r.cost.size() * sizeof(float), '\0');
  char* out = bytes.data();
  std::memcpy(out, &r.rays, 8);
  std::memcpy(out + 8, &r.cycles, 8);
  std::memcpy(out + 16, r.type_rays.data(), sizeof r.type_rays);
  std::memcpy(out + 16 + sizeof r.type_rays, r.type_cycles.data(), sizeof r.type_cycles);
  if (!r.cost.empty()) std::memcpy(out + kHeaderBytes, r.cost.data(), r.cost.size() * 4);
  return bytes;
}

DeviceResult decode(const std::string& bytes, const DeviceTask& task) {
  size_t positions = task.region.size();
  if (bytes.size() != kHeaderBytes + positions * sizeof(float))
    throw std::runtime_error("device simulation returned a malformed result");
  DeviceResult r;
  const char* in = bytes.data();
  std::memcpy(&r.rays, in, 8);
  std::memcpy(&r.cycles, in + 8, 8);
  std::memcpy(r.type_rays.data(), in + 16, sizeof r.type_rays);
  std::memcpy(r.type_cycles.data(), in + 16 + sizeof r.type_rays, sizeof r.type_cycles);
  r.cost.resize(positions);
  if (positions) std::memcpy(r.cost.data(), in + kHeaderBytes, positions * sizeof(float));
  r.time_ns = double(r.cycles) / task.config->clock_ghz;
  return r;
}

std::string simulate(const HwConfig& config, BvhView image, const DeviceTask& task,
                     const ScreenLayout& layout) {
  VectorRaySource source(task.rays);
  SlotCostListener slots(config, layout.pixels());
  RtSimulator sim(config, image, source, 0, 0, &slots);  // no pixel buffers: slots has the cost
  sim.run();
  slots.finish();
  DeviceResult r;
  r.rays = sim.rays();
  r.cycles = sim.cycles();
  r.type_rays = slots.type_rays();
  r.type_cycles = slots.type_cost();
  r.cost.assign(task.region.size(), 0.0f);
  for (uint32_t p = task.region.begin; p < task.region.end; ++p)
    r.cost[p - task.region.begin] = float(slots.pixel_cost()[layout.pixel_at(p)]);
  return encode(r);
}

}  // namespace

SystemCBackend::SystemCBackend(const TriangleMesh& mesh, const InstancedMesh& instances,
                               const InstanceSettings& settings, unsigned jobs)
    : mesh_(mesh), instances_(instances), settings_(settings), jobs_(std::max(jobs, 1u)) {
  setenv("SYSC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
}

const TwoLevelBvh& SystemCBackend::bvh_for(const HwConfig& config) {
  std::string key = resolved_json(config)["bvh"].dump();
  auto it = bvhs_.find(key);
  if (it != bvhs_.end()) return it->second;
  // A scene kept without a flattened copy gets one when a device's config asks for one level.
  bool one_level = settings_.empty() && !wants_two_levels(config.bvh, instances_);
  if (one_level && mesh_.triangle_count() == 0 && flattened_.triangle_count() == 0)
    flattened_ = flatten(instances_).mesh;
  const TriangleMesh& flat = mesh_.triangle_count() > 0 ? mesh_ : flattened_;
  return bvhs_.emplace(key, build_scene_levels(flat, instances_, config.bvh, {}, settings_))
      .first->second;
}

std::vector<DeviceResult> SystemCBackend::run(const std::vector<DeviceTask>& tasks,
                                              const ScreenLayout& layout) {
  std::vector<std::function<std::string()>> work;
  std::vector<size_t> busy;  // tasks with rays, largest first
  for (size_t i = 0; i < tasks.size(); ++i) {
    const DeviceTask& task = tasks[i];
    if (!task.config) throw std::invalid_argument("SystemCBackend: a task without hardware");
    const TwoLevelBvh& bvh = bvh_for(*task.config);
    work.push_back([&task, &bvh, &layout] { return simulate(*task.config, bvh, task, layout); });
    if (!task.rays.empty()) busy.push_back(i);
  }
  std::stable_sort(busy.begin(), busy.end(),
                   [&](size_t a, size_t b) { return tasks[a].rays.size() > tasks[b].rays.size(); });
  std::vector<std::function<std::string()>> busy_work;
  for (size_t i : busy) busy_work.push_back(work[i]);
  std::vector<std::string> texts = run_in_children(busy_work, jobs_);
  std::vector<DeviceResult> results(tasks.size());
  for (size_t i = 0; i < tasks.size(); ++i) results[i].cost.assign(tasks[i].region.size(), 0.0f);
  for (size_t k = 0; k < busy.size(); ++k) results[busy[k]] = decode(texts[k], tasks[busy[k]]);
  return results;
}

}  // namespace rtsim::multi
