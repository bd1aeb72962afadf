// The frame of several devices as a cost model, after the mGPU flow of SEED's Pica Pica
// ("Explicit heterogeneous multi-GPU, parallel fork-join"): ray generation on the primary
// (device 0), each other device's sub-region copied to it, tracing on all devices at once, the
// results copied back to the primary, filtering on the primary. Copies go through system
// memory on one copy queue (link.shared, the talk's setup; FIFO, both directions), or each
// device has a link of its own. A copy costs latency + bytes / bandwidth. Tracing times come
// from the simulated devices; ray generation and filtering cost a fixed time per pixel.
#pragma once

#include <cstdint>
#include <vector>

namespace rtsim::multi {

struct LinkConfig {
  double bandwidth_gbps = 12.0;  // GB/s: effective bandwidth of one copy
  double latency_us = 10.0;      // us: fixed cost of each copy (submission, sync)
  bool shared = true;            // one copy queue for every copy; false: a link per device
};

struct FlowConfig {
  double raygen_ns_per_pixel = 0.5;      // ns: G-buffer and ray generation on the primary
  double filter_ns_per_pixel = 1.0;      // ns: filtering (denoising) on the primary
  double input_bytes_per_pixel = 32.0;   // bytes: G-buffer of a sub-region sent to its device
  double bytes_per_sample = 8.0;         // bytes: position of each irregular sample sent
  double bytes_per_ray = 0.0;            // bytes: per ray sent, if rays are shipped themselves
  double output_bytes_per_pixel = 16.0;  // bytes: tracing results per pixel copied back
  LinkConfig link;
};

// What one device renders in a frame.
struct DeviceLoad {
  uint64_t pixels = 0, samples = 0, rays = 0;
  double trace_ns = 0;  // simulated time of tracing its rays
};

struct DeviceTiming {
  double start_ns = 0, trace_ns = 0, end_ns = 0;  // tracing, from the start of the frame
  double copy_in_ns = 0, copy_out_ns = 0;         // transfer times; 0 on the primary
  double results_ns = 0;                          // its results are on the primary
  uint64_t bytes_in = 0, bytes_out = 0;
  double busy_ns = 0;  // tracing, plus ray generation and filtering on the primary
  double idle_ns = 0;  // frame_ns - busy_ns
};

struct FrameTiming {
  double raygen_ns = 0, filter_ns = 0, frame_ns = 0;
  std::vector<DeviceTiming> devices;
  double copy_ns = 0;  // time the link(s) spent copying, summed
  uint64_t copy_bytes = 0;
  double copy_overhead_ns = 0;  // frame_ns - (raygen + longest trace + filter)
};

// The frame of devices.size() devices (device 0 is the primary) over an image of
// image_pixels pixels.
FrameTiming time_frame(const FlowConfig& flow, uint64_t image_pixels,
                       const std::vector<DeviceLoad>& devices);

// One device alone: ray generation, tracing, filtering; nothing to copy.
double single_device_frame_ns(const FlowConfig& flow, uint64_t image_pixels, double trace_ns);

// max_i |v_i - mean| / mean, in %, as Harada & Fujita report it; 0 if the mean is 0.
double max_deviation_pct(const std::vector<double>& values);

}  // namespace rtsim::multi
