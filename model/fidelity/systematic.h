// Estimates from a systematic sample: one unit in every k of a population in order (the scale
// model measures one warp in every `rate`). The variance comes from the successive differences
// of the units in sample order, the usual estimator for a single systematic sample (Cochran,
// Sampling Techniques, 3rd ed., section 8.11): s^2 ~ sum (y_i - y_(i-1))^2 / (2 (n - 1)), and
// V(k sum y) = k^2 (1 - 1/k) n s^2. Ratios (hit rates, per-ray means) use the linearised
// variance of y - R x. Values are accumulated one unit at a time, so nothing is stored per
// unit. Intervals are 95% (1.96 standard errors).
#pragma once

#include <cstdint>

#include "model/fidelity/fidelity_result.h"

namespace rtsim {

class SystematicSeries {
 public:
  void add(double y, double x = 0);  // the next unit of the sample, in population order
  uint64_t units() const { return n_; }
  double sum_y() const { return sy_; }
  double sum_x() const { return sx_; }
  // k sum(y) + offset, with its interval; k is the population over the sample.
  Estimate total(double k, double offset = 0) const;
  // (k sum(y) + y_offset) / (k sum(x) + x_offset); unknown if the denominator is 0.
  Estimate ratio(double k, double y_offset = 0, double x_offset = 0) const;

 private:
  double variance(double k, double r) const;  // of k sum(y - r x)

  uint64_t n_ = 0;
  double sy_ = 0, sx_ = 0;
  double dyy_ = 0, dxx_ = 0, dxy_ = 0;  // sums of squared and crossed successive differences
  double last_y_ = 0, last_x_ = 0;
};

}  // namespace rtsim
