#include "ridefit/road/resample.h"

// Boost 1.74's pchip.hpp calls an unqualified isnan; <math.h> declares ::isnan for it.
#include <math.h>  // NOLINT(modernize-deprecated-headers)

#include <boost/math/interpolators/pchip.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ridefit::road {

UniformSamples resample_uniform(std::span<const double> x, std::span<const double> y) {
  const std::size_t n = x.size();
  if (n != y.size() || n < 4) {
    throw std::invalid_argument("resample_uniform: needs at least 4 (x, y) pairs of equal count");
  }
  std::vector<double> spacing(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) spacing[k] = x[k + 1] - x[k];
  std::vector<double> sorted = spacing;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2),
                   sorted.end());
  const double median = sorted[sorted.size() / 2];
  const double span = x[n - 1] - x[0];

  const bool uniform = std::all_of(spacing.begin(), spacing.end(), [median](double dx) {
    return std::abs(dx - median) <= 1e-6 * median;
  });
  if (uniform) {
    return {x[0], span / static_cast<double>(n - 1), std::vector<double>(y.begin(), y.end())};
  }

  const auto count = static_cast<std::size_t>(std::llround(span / median)) + 1;
  const double step = span / static_cast<double>(count - 1);
  boost::math::interpolators::pchip<std::vector<double>> interpolant(
      std::vector<double>(x.begin(), x.end()), std::vector<double>(y.begin(), y.end()));
  UniformSamples result{x[0], step, std::vector<double>(count)};
  for (std::size_t k = 0; k < count; ++k) {
    // Clamp so rounding never asks the interpolant for a point beyond x_{n−1}.
    const double xk = std::min(x[0] + step * static_cast<double>(k), x[n - 1]);
    result.values[k] = interpolant(xk);
  }
  return result;
}

}  // namespace ridefit::road
