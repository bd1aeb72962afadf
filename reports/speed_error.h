// `rtsim speed-vs-error`: every fidelity level (and the sampled level at each rate) against
// the full cycle-approximate run of the same stream and config: host time, speed-up, and the
// error in cycles, DRAM bytes and hit rates, with the sampled level's 95% intervals.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/fidelity/fidelity_result.h"

namespace rtsim::reports {

struct LevelRun {
  std::string label;  // "cycle", "functional", "cache", "sampled 1/16"
  FidelityResult result;
  std::vector<FidelityResult> other_seeds;  // sampled level: the same rate with other seeds
};

constexpr const char* kSpeedErrorSchema = "rtsim.speed_vs_error/1";

// reference: the full cycle run; runs: the others. context: workload, config, stream.
nlohmann::ordered_json speed_error_json(const LevelRun& reference,
                                        const std::vector<LevelRun>& runs,
                                        const nlohmann::ordered_json& context);

// The table printed on the terminal (and the Markdown file, with markdown = true).
std::string speed_error_table(const nlohmann::ordered_json& doc, bool markdown);

// The Markdown page: what was compared, the goal, and the table.
std::string speed_error_markdown(const nlohmann::ordered_json& doc);

// One CSV row per level: label, host seconds, speed-up, each metric, its error and interval.
std::string speed_error_csv(const nlohmann::ordered_json& doc);

}  // namespace rtsim::reports
