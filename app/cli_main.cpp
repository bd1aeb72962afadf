#include "app/cli_main.h"

#include <exception>

#include <fmt/core.h>

#include "model/sc/stall_watchdog.h"
#include "traces/error.h"

// SystemC's library needs the symbol; main() is ours.
extern "C" int sc_main(int, char**) {
  return 0;
}

namespace rtsim::app {
namespace {

// A usage error as one line: CLI11's message, naming the command and where help is; an unknown
// or missing command lists the commands.
std::string usage_problem(const CLI::App& app, int argc, char** argv, const CLI::ParseError& e,
                          const std::string& program) {
  std::string commands;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    commands += (commands.empty() ? "" : ", ") + sub->get_name();
  std::string first = argc > 1 ? argv[1] : "";
  if (first.empty() || first[0] == '-')
    return "a command is required (" + commands + "; " + program + " --help describes them)";
  const CLI::App* command = nullptr;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (sub->get_name() == first) command = sub;
  if (!command) return "unknown command '" + first + "' (commands: " + commands + ")";
  return first + ": " + e.what() + " (" + program + " " + first + " --help lists the options)";
}

}  // namespace

int run_command_line(CLI::App& app, int argc, char** argv, const std::string& program,
                     const int& exit_code) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "{}: error: {}\n", program, usage_problem(app, argc, argv, e, program));
    return 2;
  } catch (const rtsim::InputError& e) {
    fmt::print(stderr, "{}: error: {}\n", program, e.what());
    return 2;
  } catch (const rtsim::SimStallError& e) {  // the state dump ends its own lines
    fmt::print(stderr, "{}: stall: {}", program, e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}: internal error: {}\n", program, e.what());
    return 3;
  }
  return exit_code;
}

}  // namespace rtsim::app
