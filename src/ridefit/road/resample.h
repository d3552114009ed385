#pragma once

#include <span>
#include <vector>

namespace ridefit::road {

// Samples on a uniform grid x_k = start + k·step.
struct UniformSamples {
  double start = 0.0;
  double step = 0.0;
  std::vector<double> values;
};

// Brings samples (x_k, y_k) with strictly increasing x onto a uniform grid from x_0 to
// x_{n−1}, for UniformSpline. Already-uniform data (every spacing within 1e-6 of the median
// spacing, relative) is kept exactly as it is. Otherwise the grid spacing is the median
// input spacing (robust to a few odd gaps) and values come from monotone piecewise-cubic
// Hermite interpolation (PCHIP), which neither overshoots at steps nor invents extrema
// between measured points. Needs at least 4 points; x is assumed already checked.
UniformSamples resample_uniform(std::span<const double> x, std::span<const double> y);

}  // namespace ridefit::road
