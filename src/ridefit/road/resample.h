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
// between measured points; the grid has at least 5 points (what UniformSpline needs), even
// when a few wide gaps make the median spacing larger than a quarter of the span. Needs at
// least 4 points; x is assumed already checked (strictly increasing, finite), and
// resampled_count(x) <= kMaxRoadSamples (road_limits.h), else std::invalid_argument.
UniformSamples resample_uniform(std::span<const double> x, std::span<const double> y);

// The number of points resample_uniform puts on x's grid: x.size() for uniform data, else
// round(span/median spacing) + 1, at least 5. A double, as absurd spacings (a 1 nm gap among
// metres) give counts beyond memory or any integer type: check it before resampling.
double resampled_count(std::span<const double> x);

}  // namespace ridefit::road
