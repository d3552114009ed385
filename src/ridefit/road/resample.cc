#include "ridefit/road/resample.h"

// Boost 1.74's pchip.hpp calls an unqualified isnan; <math.h> declares ::isnan for it.
#include <math.h>  // NOLINT(modernize-deprecated-headers)

#include <boost/math/interpolators/pchip.hpp>

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ridefit/road/road_limits.h"

namespace ridefit::road {
namespace {

constexpr double kMinimumGridPoints = 5.0;  // what UniformSpline needs without end slopes

struct Grid {
  bool uniform = false;
  double count = 0.0;  // a double: absurd spacings give a count beyond any integer type
};

Grid plan_grid(std::span<const double> x) {
  const std::size_t n = x.size();
  if (n < 4) throw std::invalid_argument("resample_uniform: needs at least 4 (x, y) pairs");
  std::vector<double> spacing(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) spacing[k] = x[k + 1] - x[k];
  std::vector<double> sorted = spacing;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2),
                   sorted.end());
  const double median = sorted[sorted.size() / 2];
  const bool uniform = std::all_of(spacing.begin(), spacing.end(), [median](double dx) {
    return std::abs(dx - median) <= 1e-6 * median;
  });
  if (uniform) return {true, static_cast<double>(n)};
  const double span = x[n - 1] - x[0];
  return {false, std::max(std::round(span / median) + 1.0, kMinimumGridPoints)};
}

}  // namespace

double resampled_count(std::span<const double> x) { return plan_grid(x).count; }

UniformSamples resample_uniform(std::span<const double> x, std::span<const double> y) {
  const std::size_t n = x.size();
  if (n != y.size()) {
    throw std::invalid_argument("resample_uniform: needs (x, y) pairs of equal count");
  }
  const Grid grid = plan_grid(x);
  const double span = x[n - 1] - x[0];
  if (grid.uniform) {
    return {x[0], span / static_cast<double>(n - 1), std::vector<double>(y.begin(), y.end())};
  }
  if (!(grid.count <= kMaxRoadSamples)) {
    throw std::invalid_argument(fmt::format(
        "resample_uniform: {:.3g} grid points, more than {:g}; check resampled_count() first",
        grid.count, kMaxRoadSamples));
  }

  const auto count = static_cast<std::size_t>(grid.count);
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
