#pragma once

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>

#include <cstddef>
#include <limits>
#include <vector>

namespace ridefit::road {

// A signal sampled on a uniform grid x_k = start + k·step (k = 0 … n−1), interpolated by a
// C2 cubic B-spline (boost::math cardinal_cubic_b_spline): the curve passes through every
// sample, and its value, slope and curvature are continuous, so h and dh/dt are continuous
// for the integrators. Error O(step^4) for smooth signals; the slope comes from the same
// spline, not from differences.
//
// The end slopes of the spline are given (e.g. 0 for a profile that starts flat) or, when
// NaN, estimated by fourth-order one-sided differences. Outside [start, end] the signal holds
// its end value with slope 0: h stays continuous there, and dh/dx is continuous too whenever
// the end slope is 0 (true for every generated road here; a measured signal may jump in
// slope at its ends).
//
// Copying is cheap: copies share the spline coefficients.
class UniformSpline {
 public:
  // Needs at least 5 samples (3 if both end slopes are given) and step > 0; all finite.
  UniformSpline(const std::vector<double>& samples, double start, double step,
                double start_slope = std::numeric_limits<double>::quiet_NaN(),
                double end_slope = std::numeric_limits<double>::quiet_NaN());

  double value(double x) const;
  double derivative(double x) const;

  double start() const { return start_; }
  double end() const { return end_; }
  double step() const { return step_; }
  std::size_t size() const { return size_; }

 private:
  boost::math::interpolators::cardinal_cubic_b_spline<double> spline_;
  double start_;
  double end_;
  double step_;
  std::size_t size_;
  double start_value_;
  double end_value_;
};

}  // namespace ridefit::road
