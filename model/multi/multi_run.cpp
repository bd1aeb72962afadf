#include "model/multi/multi_run.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "model/multi/frame_reader.h"
#include "traces/error.h"

namespace rtsim::multi {
namespace {

// One frame's rays, located on the screen.
struct LocatedFrame {
  const FrameRays* source = nullptr;
  std::vector<uint32_t> position;  // per ray
  FramePreview preview;            // samples and rays by type, per position
};

LocatedFrame locate(const FrameRays& frame, const ScreenLayout& layout, SampleUnit unit) {
  LocatedFrame located{&frame, {}, {}};
  located.preview.samples.assign(layout.pixels(), 0.0);
  located.preview.rays.assign(layout.pixels(), TypedRays{});
  located.position.reserve(frame.rays.size());
  for (const Ray& ray : frame.rays) {
    if (ray.pixel >= layout.pixels())  // the stream's reader refuses such rays
      throw std::logic_error("a ray's pixel lies outside the image");
    uint32_t p = layout.position_of(ray.pixel);
    located.position.push_back(p);
    located.preview.rays[p][size_t(ray.type)] += 1;
    if (unit == SampleUnit::Rays || ray.type == RayType::Camera) located.preview.samples[p] += 1;
  }
  return located;
}

// The rays of each device's region.
std::vector<std::vector<Ray>> partition(const LocatedFrame& frame, const Split& split) {
  std::vector<std::vector<Ray>> rays(split.size());
  for (size_t i = 0; i < frame.source->rays.size(); ++i)
    rays[device_at(split, frame.position[i])].push_back(frame.source->rays[i]);
  return rays;
}

// Fills the record and the feedback of one strategy from its devices' results.
void account(const DeviceSet& set, const LocatedFrame& frame, const Split& split,
             const std::vector<uint32_t>& hardware, const DeviceTask* tasks,
             const DeviceResult* results, double single_trace_ns, FrameRecord& record,
             FrameFeedback& feedback) {
  const std::vector<double>& frame_samples = frame.preview.samples;
  uint32_t positions = uint32_t(frame_samples.size());
  feedback.split = split;
  feedback.samples = frame_samples;
  feedback.rays = frame.preview.rays;
  feedback.cost.assign(positions, 0.0);
  std::array<double, kRayTypeCount> type_rays{};
  std::vector<DeviceLoad> loads;
  std::vector<double> trace;
  for (size_t d = 0; d < split.size(); ++d) {
    DeviceFrame df;
    df.region = split[d];
    df.hardware = hardware[d];
    df.pixels = split[d].size();
    double samples = 0, camera = 0;
    for (uint32_t p = split[d].begin; p < split[d].end; ++p) {
      samples += frame_samples[p];
      camera += frame.preview.rays[p][size_t(RayType::Camera)];
      feedback.cost[p] = results[d].cost[p - split[d].begin];
      df.cost += feedback.cost[p];
    }
    df.samples = uint64_t(camera);
    df.rays = tasks[d].rays.size();
    df.cycles = results[d].cycles;
    loads.push_back({df.pixels, df.samples, df.rays, results[d].time_ns});
    trace.push_back(results[d].time_ns);
    feedback.devices.push_back({samples, df.cost, results[d].time_ns});
    record.devices.push_back(df);
    for (int t = 0; t < kRayTypeCount; ++t) {
      type_rays[t] += results[d].type_rays[t];
      feedback.type_cost[t] += results[d].type_cycles[t];
    }
  }
  for (int t = 0; t < kRayTypeCount; ++t)
    feedback.type_cost[t] = type_rays[t] > 0 ? feedback.type_cost[t] / type_rays[t] : 0.0;
  record.timing = time_frame(set.flow, positions, loads);
  for (size_t d = 0; d < split.size(); ++d) record.devices[d].timing = record.timing.devices[d];
  record.max_deviation_pct = max_deviation_pct(trace);
  record.single_ns = single_device_frame_ns(set.flow, positions, single_trace_ns);
  record.speedup = record.timing.frame_ns > 0 ? record.single_ns / record.timing.frame_ns : 0;
}

}  // namespace

MultiRunResult run_multi_device(RayStreamReader& reader, const DeviceSet& set,
                                DeviceConfigs& configs, DeviceBackend& backend,
                                const MultiRunOptions& options) {
  const StreamHeader& header = reader.header();
  MultiRunResult result;
  result.layout = {header.width, header.height, set.order};
  result.devices = configs.devices();
  uint32_t positions = result.layout.pixels();
  if (positions == 0)
    throw_input_error(reader.path(), "header", "no pixel grid (width x height is 0)");
  uint32_t frames = header.frame_count;
  if (options.max_frames > 0) frames = std::min(frames, options.max_frames);
  std::vector<std::unique_ptr<SplitPolicy>> policies;
  for (SplitStrategy s : set.strategies) {
    policies.push_back(make_split_policy(s, result.devices, positions));
    result.runs.push_back({s, {}});
  }
  FrameReader frame_reader(reader);
  FrameRays frame;
  while (result.single_trace_ns.size() < frames && frame_reader.next(frame)) {
    if (options.progress) options.progress(frame.frame, frames);
    LocatedFrame located = locate(frame, result.layout, set.samples);
    result.rays += frame.rays.size();
    std::vector<uint32_t> hardware;
    for (uint32_t d = 0; d < result.devices; ++d) hardware.push_back(configs.index(d, frame.frame));
    const std::vector<HwConfig>& hw = configs.configs();  // complete for this frame now
    // Task 0: the whole frame on the primary alone; then the devices of each distinct split
    // (strategies that propose the same split share its simulations: first_task).
    std::vector<DeviceTask> tasks;
    tasks.push_back({&hw[hardware[0]], frame.rays, {0, 0}});
    std::vector<Split> splits;
    std::vector<size_t> first_task;
    for (const auto& policy : policies) {
      splits.push_back(policy->next_split(located.preview));
      std::string problem = split_problem(splits.back(), positions);
      if (!problem.empty()) throw std::logic_error("split policy: " + problem);
      auto same = std::find(splits.begin(), splits.end() - 1, splits.back());
      if (same != splits.end() - 1) {
        first_task.push_back(first_task[size_t(same - splits.begin())]);
        continue;
      }
      first_task.push_back(tasks.size());
      std::vector<std::vector<Ray>> rays = partition(located, splits.back());
      for (uint32_t d = 0; d < result.devices; ++d)
        tasks.push_back({&hw[hardware[d]], std::move(rays[d]), splits.back()[d]});
    }
    std::vector<DeviceResult> results = backend.run(tasks, result.layout);
    result.single_trace_ns.push_back(results[0].time_ns);
    for (size_t s = 0; s < policies.size(); ++s) {
      FrameRecord record;
      record.frame = frame.frame;
      FrameFeedback feedback;
      size_t first = first_task[s];
      account(set, located, splits[s], hardware, &tasks[first], &results[first], results[0].time_ns,
              record, feedback);
      policies[s]->observe(feedback);
      result.runs[s].frames.push_back(std::move(record));
    }
  }
  return result;
}

}  // namespace rtsim::multi
