#pragma once

#include <cmath>
#include <vector>

namespace ridefit::testing {

// The sample standard deviation of `values` over the mean of `errors`: about 1 when the reported
// standard errors say how far the values scatter between seeds.
inline double spread_over_reported_error(const std::vector<double>& values,
                                         const std::vector<double>& errors) {
  const auto n = static_cast<double>(values.size());
  double mean = 0.0, reported = 0.0;
  for (double v : values) mean += v / n;
  for (double e : errors) reported += e / static_cast<double>(errors.size());
  double variance = 0.0;
  for (double v : values) variance += (v - mean) * (v - mean) / (n - 1.0);
  return std::sqrt(variance) / reported;
}

}  // namespace ridefit::testing
