#include "ridefit/fitting/diagnose/peak_shift.h"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/special_functions/trigamma.hpp>
#include <cmath>
#include <limits>
#include <vector>

namespace ridefit::fitting::diagnose {

PeakEstimate estimate_peak(std::span<const double> f, std::span<const double> psd,
                           double degrees_of_freedom, std::span<const double> bin_correlation) {
  const std::size_t n = std::min(f.size(), psd.size());
  PeakEstimate peak{0.0, std::numeric_limits<double>::infinity()};
  if (n < 5 || !(degrees_of_freedom > 0.0)) return peak;
  std::vector<double> smooth(n);
  std::size_t top = 0;
  for (std::size_t k = 0; k < n; ++k) {
    smooth[k] = (psd[k > 0 ? k - 1 : k] + psd[k] + psd[k + 1 < n ? k + 1 : k]) / 3.0;
    if (smooth[k] > smooth[top]) top = k;
  }
  peak.frequency_Hz = f[top];
  std::size_t first = top, last = top;  // inclusive
  while (first > 0 && smooth[first - 1] >= 0.5 * smooth[top]) --first;
  while (last + 1 < n && smooth[last + 1] >= 0.5 * smooth[top]) ++last;
  first = std::min(first, top >= 2 ? top - 2 : 0);
  last = std::max(last, std::min(top + 2, n - 1));
  const auto rows = static_cast<Eigen::Index>(last - first + 1);
  if (rows < 5 || top < 1 || top + 1 >= n) return peak;  // at the band's edge: no vertex
  Eigen::MatrixXd x(rows, 3);
  Eigen::VectorXd y(rows);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const std::size_t k = first + static_cast<std::size_t>(r);
    const double u = f[k] - f[top];
    x(r, 0) = 1.0;
    x(r, 1) = u;
    x(r, 2) = u * u;
    y(r) = std::log(std::max(psd[k], 1e-300));
  }
  const Eigen::Matrix3d normal = x.transpose() * x;
  const Eigen::Vector3d beta = normal.ldlt().solve(x.transpose() * y);
  const double b = beta(1), c = beta(2);
  if (!(c < 0.0)) return peak;
  const double vertex = -b / (2.0 * c);
  const double lo = f[first] - f[top], hi = f[last] - f[top];
  if (!(vertex >= lo && vertex <= hi)) return peak;  // the parabola's top lies outside its bins
  double inflation = 1.0;
  for (std::size_t d = 1; d < bin_correlation.size(); ++d) inflation += 2.0 * bin_correlation[d];
  const double variance = boost::math::trigamma(0.5 * degrees_of_freedom) * inflation;
  const Eigen::Matrix3d covariance = variance * normal.inverse();
  const Eigen::Vector3d gradient(0.0, -1.0 / (2.0 * c), b / (2.0 * c * c));
  peak.frequency_Hz = f[top] + vertex;
  peak.standard_error_Hz = std::sqrt(gradient.dot(covariance * gradient));
  return peak;
}

PeakComparison compare_peaks(const PeakEstimate& measured, const PeakEstimate& simulated,
                             double bin_width_Hz, double alpha) {
  PeakComparison c{measured, simulated, 0.0, false};
  const double z =
      boost::math::quantile(boost::math::complement(boost::math::normal(), 0.5 * alpha));
  const double scatter = std::hypot(measured.standard_error_Hz, simulated.standard_error_Hz);
  c.threshold_Hz = std::max(2.0 * bin_width_Hz, z * scatter);
  c.significant = std::isfinite(c.threshold_Hz) &&
                  std::abs(measured.frequency_Hz - simulated.frequency_Hz) > c.threshold_Hz;
  return c;
}

}  // namespace ridefit::fitting::diagnose
