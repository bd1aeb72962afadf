// rtsim: the command line. Thin: it parses, calls the parts, prints.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "app/commands.h"
#include "traces/error.h"
#include "traces/output_file.h"
#include "workloads/pipeline/image_io.h"

namespace {

// A usage error as one line: CLI11's message, naming the command and where help is; an unknown
// or missing command lists the commands.
std::string usage_problem(const CLI::App& app, int argc, char** argv, const CLI::ParseError& e) {
  std::string commands;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    commands += (commands.empty() ? "" : ", ") + sub->get_name();
  std::string first = argc > 1 ? argv[1] : "";
  if (first.empty() || first[0] == '-')
    return "a command is required (" + commands + "; rtsim --help describes them)";
  const CLI::App* command = nullptr;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name() == first) command = sub;
  if (!command) return "unknown command '" + first + "' (commands: " + commands + ")";
  return first + ": " + e.what() + " (rtsim " + first + " --help lists the options)";
}

}  // namespace

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
  rtsim::app::add_run_command(app, exit_code);
  rtsim::app::add_report_command(app, exit_code);
  rtsim::app::add_sweep_command(app, exit_code);
  rtsim::app::add_regress_command(app, exit_code);
  rtsim::app::add_validate_command(app, exit_code);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "rtsim: error: {}\n", usage_problem(app, argc, argv, e));
    return 2;
  } catch (const rtsim::InputError& e) {
    fmt::print(stderr, "rtsim: error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "rtsim: internal error: {}\n", e.what());
    return 3;
  }
  return exit_code;
}
