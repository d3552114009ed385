#include "ridefit/signal/expected_peak.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ridefit::signal {

double spectral_moment(std::span<const double> frequency_Hz, std::span<const double> psd,
                       int order) {
  if (frequency_Hz.size() != psd.size()) {
    throw std::invalid_argument("spectral_moment: frequency and PSD lengths differ");
  }
  double sum = 0.0;
  auto integrand = [&](std::size_t k) {
    return std::pow(frequency_Hz[k], order + 1) * psd[k];  // f^k·S·f: d f = f·d ln f
  };
  for (std::size_t k = 0; k + 1 < psd.size(); ++k) {
    sum +=
        0.5 * (integrand(k) + integrand(k + 1)) * std::log(frequency_Hz[k + 1] / frequency_Hz[k]);
  }
  return sum;
}

double expected_gaussian_peak(double m0, double m2, double duration_s) {
  if (!(m0 >= 0.0) || !(m2 >= 0.0) || !(duration_s > 0.0)) {
    throw std::invalid_argument("expected_gaussian_peak: moments and duration must be >= 0");
  }
  if (m0 == 0.0) return 0.0;
  const double crossing_rate_Hz = std::sqrt(m2 / m0);
  const double excursions = std::max(2.0 * crossing_rate_Hz * duration_s, std::exp(2.0));
  const double root = std::sqrt(2.0 * std::log(excursions));
  return std::sqrt(m0) * (root + std::numbers::egamma / root);
}

}  // namespace ridefit::signal
