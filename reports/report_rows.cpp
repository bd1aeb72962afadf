// The labelled values of a run report's sections, declared once: report.html shows every row,
// report.md the brief ones.
#include "reports/report_pages.h"

namespace rtsim::reports {

const std::vector<Row>& summary_rows() {
  static const std::vector<Row> rows{
      {"workload", "workload.name", Style::Text, false},
      {"hardware", "hardware.name", Style::Text, false},
      {"what limits it (busiest resource)", "timing.bottleneck.text", Style::Text},
      {"fidelity level", "timing.level", Style::Text},
      {"rays", "timing.rays", Style::Integer},
      {"cycles", "timing.cycles", Style::Integer},
      {"MRays/s", "timing.mrays_per_second", Style::Real},
      {"DRAM bytes per ray", "bandwidth.dram_bytes_per_ray", Style::Real},
      {"L1 hit rate", "bandwidth.l1_hit_rate", Style::Percent},
      {"L2 hit rate", "bandwidth.l2_hit_rate", Style::Percent},
      {"unexplained mismatches", "verification.unexplained", Style::Integer, false}};
  return rows;
}

const std::vector<Row>& workload_rows() {
  static const std::vector<Row> rows{{"workload", "workload.name", Style::Text, false},
                                     {"scene", "workload.scene", Style::Text},
                                     {"triangles", "workload.triangles", Style::Integer},
                                     {"width", "workload.width", Style::Integer},
                                     {"height", "workload.height", Style::Integer},
                                     {"frames", "workload.frames", Style::Integer},
                                     {"lights", "workload.lights", Style::Integer, false},
                                     {"rays", "workload.rays", Style::Integer},
                                     {"ray mix", "workload.ray_mix", Style::Text, true, true}};
  return rows;
}

const std::vector<Row>& hardware_rows() {
  static const std::vector<Row> rows{
      {"preset", "hardware.name", Style::Text},
      {"description", "hardware.description", Style::Text, false},
      {"config file", "hardware.config_file", Style::Text},
      {"clock (GHz)", "hardware.clock_ghz", Style::Real},
      {"RT units", "hardware.rt_units", Style::Integer},
      {"traversal", "hardware.mode", Style::Text},
      {"ray slots", "hardware.ray_slots", Style::Integer, false},
      {"L1 bytes (per unit)", "hardware.l1.size_bytes", Style::Integer},
      {"L1 hit latency", "hardware.l1.hit_latency", Style::Integer, false},
      {"L2 bytes", "hardware.l2.size_bytes", Style::Integer},
      {"L2 hit latency", "hardware.l2.hit_latency", Style::Integer, false},
      {"DRAM model", "hardware.dram.model", Style::Text, false},
      {"DRAM bytes/cycle (simple model)", "hardware.dram.bytes_per_cycle", Style::Real, false},
      {"DRAM latency (simple model)", "hardware.dram.latency", Style::Integer, false},
      {"BVH", "hardware.bvh", Style::Text},
      {"on-chip bytes", "hardware.on_chip_bytes", Style::Integer}};
  return rows;
}

const std::vector<Row>& two_level_rows() {
  static const std::vector<Row> rows{
      {"instance transforms per ray", "coherence.instances_per_ray", Style::Real},
      {"TLAS nodes per ray", "coherence.tlas_nodes_per_ray", Style::Real},
      {"BLAS nodes per ray", "coherence.blas_nodes_per_ray", Style::Real},
      {"TLAS L1 miss rate", "coherence.tlas_l1_miss_rate", Style::Percent},
      {"BLAS L1 miss rate", "coherence.blas_l1_miss_rate", Style::Percent},
      {"TLAS L2 miss rate", "coherence.tlas_l2_miss_rate", Style::Percent, false},
      {"BLAS L2 miss rate", "coherence.blas_l2_miss_rate", Style::Percent, false},
      {"TLAS DRAM bytes per ray", "coherence.tlas_dram_bytes_per_ray", Style::Real},
      {"BLAS DRAM bytes per ray", "coherence.blas_dram_bytes_per_ray", Style::Real}};
  return rows;
}

const std::vector<Row>& timing_rows() {
  static const std::vector<Row> rows{
      {"fidelity level", "timing.level", Style::Text, false},
      {"time model", "timing.time_model", Style::Text},
      {"caveat", "timing.caveat", Style::Text, true, true},
      {"cycles", "timing.cycles", Style::Integer},
      {"cycles, 95% interval (±)", "timing.cycles_ci95", Style::Integer, true, true},
      {"clock (GHz)", "timing.clock_ghz", Style::Real},
      {"MRays/s at the clock", "timing.mrays_per_second", Style::Real},
      {"rays per cycle", "timing.rays_per_cycle", Style::Real, false},
      {"host seconds (simulation)", "timing.host_seconds", Style::Real, false}};
  return rows;
}

const std::vector<Row>& bandwidth_rows() {
  static const std::vector<Row> rows{
      {"L1 bytes per ray (requested by the units)", "bandwidth.l1_bytes_per_ray", Style::Real},
      {"L2 bytes per ray (L1 misses)", "bandwidth.l2_bytes_per_ray", Style::Real},
      {"DRAM bytes per ray (L2 misses and write-backs of spilled stacks)",
       "bandwidth.dram_bytes_per_ray", Style::Real},
      {"L1 hit rate (block accesses that hit)", "bandwidth.l1_hit_rate", Style::Percent, false},
      {"L1 served without going below (hits and merges into misses in flight)",
       "bandwidth.l1_served_rate", Style::Percent},
      {"L2 hit rate (block accesses that hit)", "bandwidth.l2_hit_rate", Style::Percent, false},
      {"L2 served without going below (hits and merges into misses in flight)",
       "bandwidth.l2_served_rate", Style::Percent},
      {"L1 misses that are compulsory (first reference to the block at that L1)",
       "bandwidth.l1_compulsory_share", Style::Percent},
      {"L2 misses that are compulsory (first reference to the block)",
       "bandwidth.l2_compulsory_share", Style::Percent},
      {"DRAM bytes", "bandwidth.dram_bytes", Style::Integer, false},
      {"DRAM bytes per cycle", "bandwidth.dram_bytes_per_cycle", Style::Real, false},
      {"DRAM utilisation", "bandwidth.dram_utilisation", Style::Percent}};
  return rows;
}

const std::vector<Row>& dram_rows() {
  static const std::vector<Row> rows{
      {"model", "dram.model", Style::Text},
      {"preset", "dram.preset", Style::Text},
      {"channels", "dram.channels", Style::Integer},
      {"peak GB/s", "dram.peak_gb_per_s", Style::Real},
      {"data bus utilisation (mean over channels)", "dram.utilisation", Style::Percent},
      {"row hit rate (bursts whose row was open)", "dram.row_hit_rate", Style::Percent},
      {"row conflict rate (bursts that found another row open)", "dram.row_conflict_rate",
       Style::Percent},
      {"read latency, mean (cycles)", "dram.mean_latency", Style::Real},
      {"read latency p50 (cycles)", "dram.latency_p50", Style::Integer},
      {"read latency p90 (cycles)", "dram.latency_p90", Style::Integer, false},
      {"read latency p99 (cycles)", "dram.latency_p99", Style::Integer},
      {"read latency max (cycles)", "dram.latency_max", Style::Integer, false},
      {"bursts queued per channel (mean)", "dram.queue_occupancy", Style::Real, false},
      {"read-write turnarounds", "dram.turnarounds", Style::Integer, false},
      {"refresh stall (DRAM clocks)", "dram.refresh_stall_clocks", Style::Integer, false}};
  return rows;
}

const std::vector<Row>& energy_rows() {
  static const std::vector<Row> rows{
      {"process node", "energy.node", Style::Text},
      {"energy per ray (nJ)", "energy.nj_per_ray", Style::Real},
      {"MRays/J", "energy.mrays_per_joule", Style::Real},
      {"average power (W)", "energy.power_w", Style::Real},
      {"dynamic energy (nJ)", "energy.dynamic_nj", Style::Real, false},
      {"static energy (nJ, leakage and background over the run)", "energy.static_nj", Style::Real,
       false},
      {"area on chip (mm²)", "energy.area_mm2", Style::Real},
      {"SRAM area (mm²)", "energy.sram_area_mm2", Style::Real}};
  return rows;
}

const std::vector<Column>& energy_structure_columns() {
  static const std::vector<Column> columns{{"event", "event", int(Style::Text)},
                                           {"events", "events", int(Style::Integer)},
                                           {"pJ/event", "pj_per_event", int(Style::Real)},
                                           {"dynamic nJ", "dynamic_nj", int(Style::Real)},
                                           {"static nJ", "static_nj", int(Style::Real)},
                                           {"area mm²", "area_mm2", int(Style::Real)}};
  return columns;
}

}  // namespace rtsim::reports
