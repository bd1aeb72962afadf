// The pictures and charts of a run report: which exist, their files under images/ and the
// captions the pages print beside them. The charts are drawn by reports/charts/run_charts.py.
#include "reports/report_doc.h"

namespace rtsim::reports {

nlohmann::ordered_json report_images(const nlohmann::ordered_json& r, bool has_preview,
                                     bool has_pixels) {
  using Json = nlohmann::ordered_json;
  std::string level = r["fidelity"]["level"].get<std::string>();
  std::string not_modelled = "not modelled at the " + level + " fidelity level";
  bool histogram = !r["latency"]["histogram"].is_null();
  bool hit_rates = !r["hit_rates"]["by_type"].empty();
  bool time = !r["time"]["ray_time_share"].empty();
  bool energy = !r["energy"].is_null();
  struct Entry {
    const char *id, *kind, *title, *caption;
    bool available;
    std::string reason;
  };
  const Entry entries[] = {
      {"preview", "picture", "Preview",
       "The last traced frame, shaded from the passes' own results (direct light with the "
       "shadow rays' visibility, GI, AO, reflections, refraction).",
       has_preview, "the trace wrote no preview"},
      {"density", "picture", "Ray density",
       "Rays per pixel over the whole run, every pass together (log scale, black = none).",
       has_preview, "the trace wrote no preview"},
      {"heatmap_cycles", "heatmap", "Heatmap: cycles per pixel",
       "Sum of the latencies (cycles from dispatch to retirement) of the pixel's rays.", has_pixels,
       not_modelled},
      {"heatmap_nodes", "heatmap", "Heatmap: nodes visited per pixel",
       "BVH nodes fetched by the pixel's rays (trav_nodes).", has_pixels, not_modelled},
      {"heatmap_dram_bytes", "heatmap", "Heatmap: DRAM bytes per pixel",
       "Bytes the L2 fetched from DRAM on behalf of the pixel's rays, plus their stack spills.",
       has_pixels, not_modelled},
      {"chart_latency", "chart", "Latency distribution per ray type",
       "Share of each ray type's rays by latency (cycles from dispatch to retirement, log "
       "bins of a quarter octave); dashed lines mark the medians.",
       histogram, not_modelled},
      {"chart_hit_rates", "chart", "Hit rates per ray type",
       "L1 and L2 hit rates of the line accesses each ray type made; the lines mark the "
       "overall rates.",
       hit_rates, not_modelled},
      {"chart_time", "chart", "Where the time went",
       "Left: each ray type's share of the ray-slot time (the sum of its rays' latencies). "
       "Middle: how busy the units were. Right: rays retired over time, per ray type.",
       time, not_modelled},
      {"chart_energy", "chart", "Where the energy went",
       "Left: energy per ray of each structure, dynamic (events) and static (leakage and DRAM "
       "background over the run). Right: dynamic energy per ray of each ray type.",
       energy, "the energy model counts the events of a cycle-level run"},
  };
  Json images = Json::array();
  for (const Entry& e : entries)
    images.push_back({{"id", e.id},
                      {"file", std::string("images/") + e.id + ".png"},
                      {"kind", e.kind},
                      {"title", e.title},
                      {"caption", e.caption},
                      {"available", e.available},
                      {"reason", e.available ? "" : e.reason}});
  return images;
}

}  // namespace rtsim::reports
