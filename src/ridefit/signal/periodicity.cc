#include "ridefit/signal/periodicity.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ridefit::signal {
namespace {

double relative_spread(const std::vector<double>& values) {
  double mean = 0.0;
  for (double v : values) mean += v / static_cast<double>(values.size());
  double squares = 0.0;
  for (double v : values) squares += (v - mean) * (v - mean);
  return mean != 0.0 ? std::sqrt(squares / static_cast<double>(values.size())) / std::abs(mean)
                     : 1.0;
}

}  // namespace

bool looks_periodic(std::span<const double> time_s, std::span<const double> x) {
  const std::size_t n = std::min(time_s.size(), x.size());
  if (n < 8) return false;
  double mean = 0.0;
  for (std::size_t k = 0; k < n; ++k) mean += x[k] / static_cast<double>(n);
  std::vector<std::size_t> up;
  for (std::size_t k = 1; k < n; ++k) {
    if (x[k - 1] < mean && x[k] >= mean) up.push_back(k);
  }
  if (up.size() < 3) return false;
  std::vector<double> durations, excursions;
  for (std::size_t c = 0; c + 1 < up.size(); ++c) {
    durations.push_back(time_s[up[c + 1]] - time_s[up[c]]);
    const auto [lo, hi] = std::minmax_element(x.begin() + static_cast<std::ptrdiff_t>(up[c]),
                                              x.begin() + static_cast<std::ptrdiff_t>(up[c + 1]));
    excursions.push_back(*hi - *lo);
  }
  return relative_spread(durations) < 0.05 && relative_spread(excursions) < 0.10;
}

}  // namespace ridefit::signal
