// Runs commands as child processes, a fixed number at a time (the local cores by default), and
// reports each one's exit as it happens. Sweeps and regression suites run one `rtsim run` per
// point this way: each in its own process (SystemC elaborates once per process), output to a
// log file, nothing shared but the files they read.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rtsim::reports {

struct ProcessJob {
  std::vector<std::string> argv;  // argv[0]: the program's path
  std::string log;                // stdout and stderr go here
};

// The path of this executable (to run `rtsim run` children).
std::string self_executable();

// The argv of a quiet `rtsim run` child of this executable on a trace folder, writing only
// report.json into out_dir; the config is left out when empty.
std::vector<std::string> run_child_argv(const std::string& trace_dir, const std::string& out_dir,
                                        const std::string& fidelity, uint32_t sample_rate,
                                        const std::string& config);

// The FNV-1a hash of this executable's bytes, in hex: results computed by another build of
// rtsim are not reused (sweep points).
std::string executable_fingerprint();

// The full path of a program found on PATH, or "" (sbatch, squeue).
std::string find_on_path(const std::string& program);

struct CommandOutput {
  int exit_code = 0;  // as run_processes reports it
  std::string stdout_text, stderr_text;
};

// Runs argv (argv[0] a full path) to its end and returns what it printed.
CommandOutput run_command(const std::vector<std::string>& argv);

// Local cores (at least 1): the CPUs this process may run on (its affinity mask).
uint32_t local_cores();

// Runs every job, at most `parallel` at once; done(index, exit code, wall seconds) is called in
// this process as each finishes (exit code 128 + signal if a child was killed, 127 if it could
// not start).
void run_processes(const std::vector<ProcessJob>& jobs, uint32_t parallel,
                   const std::function<void(size_t, int, double)>& done);

}  // namespace rtsim::reports
