#include "ridefit/fitting/diagnose/pooled_bands.h"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/special_functions/trigamma.hpp>
#include <cmath>

namespace ridefit::fitting::diagnose {

std::vector<PooledBand> significant_pooled_bands(std::span<const double> log_ratio,
                                                 double bin_variance,
                                                 std::span<const double> bin_correlation,
                                                 double alpha, std::size_t max_width_bins) {
  std::vector<PooledBand> out;
  const std::size_t n = log_ratio.size();
  const std::size_t widest = std::min(max_width_bins, n);
  if (widest < 2 || !(bin_variance > 0.0)) return out;
  auto step_of = [](std::size_t w) { return std::max<std::size_t>(1, w / 2); };
  std::size_t tests = 0;
  for (std::size_t w = 2; w <= widest; w *= 2) tests += (n - w) / step_of(w) + 1;
  const double z_limit = boost::math::quantile(
      boost::math::complement(boost::math::normal(), 0.5 * alpha / static_cast<double>(tests)));
  auto rho = [&](std::size_t d) { return d < bin_correlation.size() ? bin_correlation[d] : 0.0; };
  for (std::size_t w = 2; w <= widest; w *= 2) {
    // Σ_i Σ_j ρ(|i − j|) = w + 2·Σ_d (w − d)·ρ(d).
    double pairs = static_cast<double>(w);
    for (std::size_t d = 1; d < w; ++d) pairs += 2.0 * static_cast<double>(w - d) * rho(d);
    const double sd = std::sqrt(bin_variance * pairs) / static_cast<double>(w);
    for (std::size_t first = 0; first + w <= n; first += step_of(w)) {
      double mean = 0.0;
      for (std::size_t k = first; k < first + w; ++k) mean += log_ratio[k];
      mean /= static_cast<double>(w);
      const double z = mean / sd;
      if (std::abs(z) > z_limit) out.push_back({first, first + w, mean, z});
    }
  }
  return out;
}

double log_ratio_variance(std::span<const double> log_ratio, double degrees_of_freedom,
                          std::span<const double> bin_correlation, double floor_variance) {
  const double independent = 2.0 * boost::math::trigamma(0.5 * degrees_of_freedom);
  if (log_ratio.size() < 8) return std::max(independent, floor_variance);
  std::vector<double> second;
  for (std::size_t k = 1; k + 1 < log_ratio.size(); ++k) {
    second.push_back(log_ratio[k + 1] - 2.0 * log_ratio[k] + log_ratio[k - 1]);
  }
  auto median_of = [](std::vector<double> v) {
    const auto middle = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), middle, v.end());
    return *middle;
  };
  const double center = median_of(second);
  for (double& v : second) v = std::abs(v - center);
  const double sd = 1.4826 * median_of(second);
  auto rho = [&](std::size_t d) { return d < bin_correlation.size() ? bin_correlation[d] : 0.0; };
  const double empirical = sd * sd / std::max(6.0 - 8.0 * rho(1) + 2.0 * rho(2), 1e-3);
  return std::max(std::min(independent, empirical), floor_variance);
}

}  // namespace ridefit::fitting::diagnose
