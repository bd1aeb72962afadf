// rtsim-noimage: the rtsim commands that need no image library (bench-sim), in an executable
// that does not load OpenImageIO, so that valgrind's callgrind can run it: rtsim cannot, as
// the SIMD library OpenImageIO loads runs rdtscp at load, which Debian 12's valgrind stops at.
// For instruction counts of the cycle model on a realistic workload (README, "Benchmarks").
#include <cstdlib>

#include <CLI/CLI.hpp>

#include "app/cli_main.h"
#include "app/commands.h"
#include "traces/output_file.h"

int main(int argc, char** argv) {
  setenv("SYSC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
  rtsim::remove_temporaries_on_signals();
  CLI::App app{"rtsim-noimage " RTSIM_VERSION
               ": the rtsim commands that need no image library, for valgrind"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "rtsim-noimage " RTSIM_VERSION);
  int exit_code = 0;
  rtsim::app::add_bench_sim_command(app, exit_code);
  return rtsim::app::run_command_line(app, argc, argv, "rtsim-noimage", exit_code);
}
