#include "model/fidelity/stratified.h"

#include <cmath>
#include <numeric>

namespace rtsim {

double collapsed_strata_variance(const std::vector<double>& t) {
  size_t n = t.size();
  if (n < 2) return 0;
  double variance = 0;
  for (size_t first = 0; first < n;) {
    size_t size = (n - first == 3) ? 3 : 2;
    double mean = 0;
    for (size_t i = first; i < first + size; ++i) mean += t[i] / double(size);
    double squares = 0;
    for (size_t i = first; i < first + size; ++i) squares += (t[i] - mean) * (t[i] - mean);
    variance += double(size) / double(size - 1) * squares;
    first += size;
  }
  return variance;
}

Estimate total_estimate(const std::vector<double>& t, double offset) {
  double total = std::accumulate(t.begin(), t.end(), 0.0) + offset;
  return {true, total, 1.96 * std::sqrt(collapsed_strata_variance(t))};
}

Estimate ratio_estimate(const std::vector<double>& y, const std::vector<double>& x, double y_offset,
                        double x_offset) {
  double sy = std::accumulate(y.begin(), y.end(), 0.0) + y_offset;
  double sx = std::accumulate(x.begin(), x.end(), 0.0) + x_offset;
  if (sx <= 0) return {};
  double r = sy / sx;
  std::vector<double> z(y.size());
  for (size_t i = 0; i < y.size(); ++i) z[i] = y[i] - r * x[i];
  return {true, r, 1.96 * std::sqrt(collapsed_strata_variance(z)) / sx};
}

}  // namespace rtsim
