// The run summary printed by `rtsim trace`: rays per pass against the settings' budget, how
// many of them met alpha-tested candidates, and which passes were skipped and why.
#pragma once

#include <string>

#include "workloads/pipeline/pipeline.h"

namespace rtsim::pipeline {

std::string format_summary(const RunSummary& summary);

}  // namespace rtsim::pipeline
