// rtsim: the command line. Thin: it parses, calls the parts, prints.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

#include "app/cli_main.h"
#include "app/commands.h"
#include "traces/output_file.h"
#include "workloads/pipeline/image_io.h"

int main(int argc, char** argv) {
  // SystemC's banner would precede every simulation's output; children inherit this.
  setenv("SYSC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
  rtsim::remove_temporaries_on_signals();
  rtsim::set_alpha_image_reader(rtsim::pipeline::read_texture_alpha);
  CLI::App app{"rtsim " RTSIM_VERSION ": cycle-approximate simulator of ray-tracing hardware"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "rtsim " RTSIM_VERSION);
  int exit_code = 0;
  rtsim::app::add_scene_info_command(app, exit_code);
  rtsim::app::add_trace_info_command(app, exit_code);
  rtsim::app::add_hardcases_command(app, exit_code);
  rtsim::app::add_trace_command(app, exit_code);
  rtsim::app::add_bench_trace_command(app, exit_code);
  rtsim::app::add_verify_command(app, exit_code);
  rtsim::app::add_bench_command(app, exit_code);

  rtsim::app::add_sim_command(app, exit_code);
  rtsim::app::add_bench_sim_command(app, exit_code);
  rtsim::app::add_multi_device_command(app, exit_code);
  rtsim::app::add_speed_vs_error_command(app, exit_code);
  rtsim::app::add_curve_command(app, exit_code);
  rtsim::app::add_run_command(app, exit_code);
  rtsim::app::add_report_command(app, exit_code);
  rtsim::app::add_compare_command(app, exit_code);
  rtsim::app::add_sweep_command(app, exit_code);
  rtsim::app::add_regress_command(app, exit_code);
  rtsim::app::add_validate_command(app, exit_code);

  return rtsim::app::run_command_line(app, argc, argv, "rtsim", exit_code);
}
