// The command line's parse and its errors, shared by rtsim and rtsim-noimage: a usage error or
// bad input is one line naming the program and exit code 2, a simulation stall (its state dump)
// exit code 1, any other failure exit code 3.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace rtsim::app {

// Parses argv into app (whose callbacks run the command and set exit_code); returns the
// process's exit code.
int run_command_line(CLI::App& app, int argc, char** argv, const std::string& program,
                     const int& exit_code);

}  // namespace rtsim::app
