#include "model/fidelity/systematic.h"

#include <cmath>

namespace rtsim {

void SystematicSeries::add(double y, double x) {
  if (n_ > 0) {
    double dy = y - last_y_, dx = x - last_x_;
    dyy_ += dy * dy;
    dxx_ += dx * dx;
    dxy_ += dy * dx;
  }
  ++n_;
  sy_ += y;
  sx_ += x;
  last_y_ = y;
  last_x_ = x;
}

double SystematicSeries::variance(double k, double r) const {
  if (n_ < 2 || k <= 1) return 0;
  double differences = dyy_ - 2 * r * dxy_ + r * r * dxx_;
  double s2 = std::max(0.0, differences) / (2.0 * double(n_ - 1));
  return k * k * (1 - 1 / k) * double(n_) * s2;
}

Estimate SystematicSeries::total(double k, double offset) const {
  return {true, k * sy_ + offset, 1.96 * std::sqrt(variance(k, 0))};
}

Estimate SystematicSeries::ratio(double k, double y_offset, double x_offset) const {
  double y = k * sy_ + y_offset, x = k * sx_ + x_offset;
  if (x <= 0) return {};
  double r = y / x;
  return {true, r, 1.96 * std::sqrt(variance(k, r)) / x};
}

}  // namespace rtsim
