#include "ridefit/signal/psd_confidence.h"

#include <fmt/format.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/signal/spectrum_check.h"

namespace ridefit::signal {
namespace {

void check_confidence(double confidence) {
  if (!(confidence > 0.0 && confidence < 1.0)) {
    throw InputError(fmt::format(
        "PSD confidence interval: confidence {} is outside (0, 1); use e.g. 0.9 for 90 %",
        confidence));
  }
}

// ν/χ²_ν(1 − α/2) and ν/χ²_ν(α/2): the factors that turn P̂ into the bounds.
ConfidenceBounds interval_factors(double degrees_of_freedom, double confidence) {
  const boost::math::chi_squared_distribution<double> chi_squared(degrees_of_freedom);
  const double alpha = 1.0 - confidence;
  return {degrees_of_freedom / boost::math::quantile(chi_squared, 1.0 - 0.5 * alpha),
          degrees_of_freedom / boost::math::quantile(chi_squared, 0.5 * alpha)};
}

}  // namespace

ConfidenceBounds chi_squared_interval(double estimate, double degrees_of_freedom,
                                      double confidence) {
  check_confidence(confidence);
  if (!std::isfinite(estimate) || estimate < 0.0) {
    throw InputError(fmt::format(
        "PSD confidence interval: estimate {} is invalid; it must be finite and ≥ 0", estimate));
  }
  if (!std::isfinite(degrees_of_freedom) || !(degrees_of_freedom > 0.0)) {
    throw InputError(fmt::format(
        "PSD confidence interval: {} degrees of freedom are invalid; they must be finite and > 0",
        degrees_of_freedom));
  }
  const ConfidenceBounds factors = interval_factors(degrees_of_freedom, confidence);
  return {estimate * factors.lower, estimate * factors.upper};
}

PsdConfidenceInterval psd_confidence_interval(const PowerSpectralDensity& spectrum,
                                              double confidence) {
  check_confidence(confidence);
  check_psd_statistics("PSD confidence interval", "the spectrum", spectrum);
  const std::size_t n = spectrum.psd.size();
  PsdConfidenceInterval interval{std::vector<double>(n), std::vector<double>(n), confidence};
  // Quantiles cost microseconds; most bins share ν, so reuse the last factors.
  double cached_dof = 0.0;
  ConfidenceBounds factors;
  for (std::size_t k = 0; k < n; ++k) {
    const double dof = spectrum.degrees_of_freedom[k];
    if (dof != cached_dof) {
      factors = interval_factors(dof, confidence);
      cached_dof = dof;
    }
    interval.lower[k] = spectrum.psd[k] * factors.lower;
    interval.upper[k] = spectrum.psd[k] * factors.upper;
  }
  return interval;
}

}  // namespace ridefit::signal
