#include "ridefit/road/uniform_spline.h"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

namespace ridefit::road {

UniformSpline::UniformSpline(const std::vector<double>& samples, double start, double step,
                             double start_slope, double end_slope)
    : start_(start),
      end_(start + step * static_cast<double>(samples.empty() ? 0 : samples.size() - 1)),
      step_(step),
      size_(samples.size()) {
  const bool slopes_given = !std::isnan(start_slope) && !std::isnan(end_slope);
  if (samples.size() < (slopes_given ? 3u : 5u)) {
    throw std::invalid_argument(fmt::format("UniformSpline: {} samples, at least {} are needed",
                                            samples.size(), slopes_given ? 3 : 5));
  }
  if (!(step > 0.0) || !std::isfinite(start)) {
    throw std::invalid_argument(fmt::format("UniformSpline: step {} must be > 0", step));
  }
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (!std::isfinite(samples[k])) {
      throw std::invalid_argument(fmt::format("UniformSpline: sample {} is {}", k, samples[k]));
    }
  }
  spline_ = boost::math::interpolators::cardinal_cubic_b_spline<double>(
      samples.data(), samples.size(), start, step, start_slope, end_slope);
  start_value_ = samples.front();
  end_value_ = samples.back();
}

double UniformSpline::value(double x) const {
  if (x <= start_) return start_value_;
  if (x >= end_) return end_value_;
  return spline_(x);
}

double UniformSpline::derivative(double x) const {
  if (x < start_ || x > end_) return 0.0;
  return spline_.prime(x);
}

}  // namespace ridefit::road
