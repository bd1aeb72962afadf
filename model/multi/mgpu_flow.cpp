#include "model/multi/mgpu_flow.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rtsim::multi {
namespace {

double copy_time(const LinkConfig& link, uint64_t bytes) {
  if (bytes == 0) return 0;
  return link.latency_us * 1000.0 + double(bytes) / link.bandwidth_gbps;  // 1 GB/s = 1 B/ns
}

}  // namespace

FrameTiming time_frame(const FlowConfig& flow, uint64_t image_pixels,
                       const std::vector<DeviceLoad>& devices) {
  FrameTiming f;
  f.raygen_ns = double(image_pixels) * flow.raygen_ns_per_pixel;
  f.filter_ns = double(image_pixels) * flow.filter_ns_per_pixel;
  f.devices.resize(devices.size());
  // Inputs leave the primary after ray generation, in device order on a shared queue.
  double link_free = f.raygen_ns;
  for (size_t i = 0; i < devices.size(); ++i) {
    const DeviceLoad& d = devices[i];
    DeviceTiming& t = f.devices[i];
    t.start_ns = f.raygen_ns;
    if (i > 0) {
      t.bytes_in = uint64_t(std::llround(double(d.pixels) * flow.input_bytes_per_pixel +
                                         double(d.samples) * flow.bytes_per_sample +
                                         double(d.rays) * flow.bytes_per_ray));
      t.bytes_out = uint64_t(std::llround(double(d.pixels) * flow.output_bytes_per_pixel));
      t.copy_in_ns = copy_time(flow.link, t.bytes_in);
      t.copy_out_ns = copy_time(flow.link, t.bytes_out);
      double begin = flow.link.shared ? link_free : f.raygen_ns;
      t.start_ns = begin + t.copy_in_ns;
      if (flow.link.shared) link_free = t.start_ns;
    }
    t.trace_ns = d.trace_ns;
    t.end_ns = t.start_ns + d.trace_ns;
    t.results_ns = t.end_ns;
  }
  // Results come back in the order the devices finish.
  std::vector<size_t> order(devices.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return f.devices[a].end_ns < f.devices[b].end_ns; });
  for (size_t i : order) {
    if (i == 0) continue;
    DeviceTiming& t = f.devices[i];
    double begin = flow.link.shared ? std::max(link_free, t.end_ns) : t.end_ns;
    t.results_ns = begin + t.copy_out_ns;
    if (flow.link.shared) link_free = t.results_ns;
  }
  double filter_start = 0, longest_trace = 0;
  for (const DeviceTiming& t : f.devices) {
    filter_start = std::max(filter_start, t.results_ns);
    longest_trace = std::max(longest_trace, t.trace_ns);
    f.copy_ns += t.copy_in_ns + t.copy_out_ns;
    f.copy_bytes += t.bytes_in + t.bytes_out;
  }
  f.frame_ns = std::max(filter_start, f.raygen_ns) + f.filter_ns;
  f.copy_overhead_ns = f.frame_ns - (f.raygen_ns + longest_trace + f.filter_ns);
  for (size_t i = 0; i < f.devices.size(); ++i) {
    DeviceTiming& t = f.devices[i];
    t.busy_ns = t.trace_ns + (i == 0 ? f.raygen_ns + f.filter_ns : 0.0);
    t.idle_ns = f.frame_ns - t.busy_ns;
  }
  return f;
}

double single_device_frame_ns(const FlowConfig& flow, uint64_t image_pixels, double trace_ns) {
  return double(image_pixels) * (flow.raygen_ns_per_pixel + flow.filter_ns_per_pixel) + trace_ns;
}

double max_deviation_pct(const std::vector<double>& values) {
  if (values.empty()) return 0;
  double mean = std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
  if (!(mean > 0)) return 0;
  double worst = 0;
  for (double v : values) worst = std::max(worst, std::abs(v - mean));
  return 100.0 * worst / mean;
}

}  // namespace rtsim::multi
