// Fidelity level 1, functional only: every ray of the stream through the traversal unit that
// the timing model drives (model/units/traversal.h), one after another, counting nodes,
// leaves and triangle tests per ray type. No caches and no time; the fastest level.
#pragma once

#include <string>

#include "model/bvh/two_level.h"
#include "model/fidelity/fidelity_result.h"

namespace rtsim {

// Reads the stream at `stream` (InputError on a corrupt file) and counts.
FidelityResult run_functional_level(BvhView image, const std::string& stream);

}  // namespace rtsim
