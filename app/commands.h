// Each rtsim subcommand lives in its own app/cmd_*.cpp and registers itself on the CLI here.
// A command's callback returns the process exit code: 0 ok, 1 a check failed, 2 bad input.
// Errors from bad input are thrown as rtsim::InputError; main() prints them as one line.
#pragma once

#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "model/bvh/bvh_config.h"

namespace rtsim::app {

void add_scene_info_command(CLI::App& app, int& exit_code);
void add_trace_info_command(CLI::App& app, int& exit_code);
void add_hardcases_command(CLI::App& app, int& exit_code);
void add_trace_command(CLI::App& app, int& exit_code);
void add_bench_trace_command(CLI::App& app, int& exit_code);

void add_verify_command(CLI::App& app, int& exit_code);
void add_bench_command(CLI::App& app, int& exit_code);
void add_sim_command(CLI::App& app, int& exit_code);
void add_bench_sim_command(CLI::App& app, int& exit_code);
void add_multi_device_command(CLI::App& app, int& exit_code);
void add_speed_vs_error_command(CLI::App& app, int& exit_code);
void add_curve_command(CLI::App& app, int& exit_code);
void add_run_command(CLI::App& app, int& exit_code);
void add_report_command(CLI::App& app, int& exit_code);
void add_compare_command(CLI::App& app, int& exit_code);
void add_sweep_command(CLI::App& app, int& exit_code);
void add_regress_command(CLI::App& app, int& exit_code);
void add_validate_command(CLI::App& app, int& exit_code);
// What every --config option takes, for its help (model/config/config_presets.h).
inline const std::string kConfigForms =
    "a .toml file, or a preset's name (desktop: configs/desktop.toml)";
// BVH build options shared by verify and bench (defined in cmd_verify.cpp).
void add_bvh_options(CLI::App& cmd, BvhConfig& config);
// The console line of a shader model's figures (the stats JSON's `shader`), shared by sim and
// run (defined in cmd_sim.cpp).
std::string shader_summary_line(const nlohmann::ordered_json& shader);
// The console line of the energy and area model's figures (the stats JSON's `energy`), shared
// likewise.
std::string energy_summary_line(const nlohmann::ordered_json& energy);

}  // namespace rtsim::app
