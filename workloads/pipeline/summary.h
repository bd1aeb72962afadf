// The run summary printed by `rtsim trace`: rays per pass against the settings' budget, and
// which passes were skipped and why.
#pragma once

#include <string>

#include "workloads/pipeline/pipeline.h"

namespace rtsim::pipeline {

std::string format_summary(const RunSummary& summary);

}  // namespace rtsim::pipeline
