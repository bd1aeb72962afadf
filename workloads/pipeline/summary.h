// The run summary printed by `rtsim trace`: rays per pass against the settings' budget, how
// many of them met alpha-tested candidates, and which passes were skipped and why.
#pragma once

#include <string>

#include "workloads/pipeline/pipeline.h"

namespace rtsim::pipeline {

std::string format_summary(const RunSummary& summary);

// How the ray mix differs from the one the budgets were set for, at 1920x1080: diffuse GI (and
// its light connections) have a fixed budget a frame, so at another resolution they are another
// share of the rays. One line naming each pass whose budget a pixel differs by more than 5% from
// its budget a pixel at 1080p, with both, and the gi.budget that keeps the 1080p mix; "" when
// none differs (at 1080p, or with GI off).
std::string ray_mix_note(const RunSummary& summary);

}  // namespace rtsim::pipeline
