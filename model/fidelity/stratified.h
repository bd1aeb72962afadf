// Estimates from stratified samples with one measured window per stratum. The variance of a
// total needs two units per stratum; with one, neighbouring strata are collapsed into pairs
// (a triple at the end when their number is odd), the usual conservative estimator (Cochran,
// Sampling Techniques, 3rd ed., section 5A.12). Ratios (hit rates, per-ray means) use the
// linearised variance of y - R x. Intervals are 95% (1.96 standard errors).
#pragma once

#include <vector>

#include "model/fidelity/fidelity_result.h"

namespace rtsim {

// Variance of sum(t) from the per-stratum estimates t (strata in stream order).
double collapsed_strata_variance(const std::vector<double>& t);

// sum(t) with its interval; `offset` is added to the value (a known, unsampled part).
Estimate total_estimate(const std::vector<double>& t, double offset = 0);

// (sum(y) + y_offset) / (sum(x) + x_offset) with its interval; unknown if the denominator
// is 0. The offsets are known parts that add no variance.
Estimate ratio_estimate(const std::vector<double>& y, const std::vector<double>& x,
                        double y_offset = 0, double x_offset = 0);

}  // namespace rtsim
