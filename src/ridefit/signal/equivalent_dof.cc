#include "ridefit/signal/equivalent_dof.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ridefit/common/errors.h"

namespace ridefit::signal {
namespace {

// Σ w²; throws unless the window, hop and segment count describe a Welch estimate.
double checked_window_power(std::span<const double> window, std::size_t hop,
                            std::size_t segment_count) {
  double power = 0.0;
  for (double w : window) power += w * w;
  if (window.empty() || !(power > 0.0) || !std::isfinite(power)) {
    throw InputError(fmt::format(
        "degrees of freedom: the window ({} samples) is empty, all zero or not finite; it "
        "needs finite values that are not all zero",
        window.size()));
  }
  if (hop == 0 || segment_count == 0) {
    throw InputError(
        fmt::format("degrees of freedom: hop {} and segment count {} must both be at least 1", hop,
                    segment_count));
  }
  return power;
}

// |R(D, d)|² = |Σ_n w[n]·w[n+D]·exp(−2πi·d·n/L)|².
double lagged_spectral_power(std::span<const double> window, std::size_t shift,
                             std::size_t bin_offset) {
  const std::size_t length = window.size();
  if (shift >= length) return 0.0;
  const double step = 2.0 * std::numbers::pi / static_cast<double>(length);
  double re = 0.0;
  double im = 0.0;
  for (std::size_t n = 0; n + shift < length; ++n) {
    const double product = window[n] * window[n + shift];
    // Reduce d·n modulo L before scaling, so the angle stays accurate for long windows.
    const double angle = step * static_cast<double>((bin_offset * n) % length);
    re += product * std::cos(angle);
    im -= product * std::sin(angle);
  }
  return re * re + im * im;
}

}  // namespace

double window_overlap_correlation(std::span<const double> window, std::size_t shift) {
  const double power = checked_window_power(window, 1, 1);
  double sum = 0.0;
  for (std::size_t n = 0; n + shift < window.size(); ++n) sum += window[n] * window[n + shift];
  return sum / power;
}

double welch_degrees_of_freedom(std::span<const double> window, std::size_t hop,
                                std::size_t segment_count) {
  checked_window_power(window, hop, segment_count);
  const double k = static_cast<double>(segment_count);
  double sum = 0.0;
  // Segments m·hop ≥ L apart do not overlap: ρ = 0.
  for (std::size_t m = 1; m < segment_count && m * hop < window.size(); ++m) {
    const double rho = window_overlap_correlation(window, m * hop);
    sum += (1.0 - static_cast<double>(m) / k) * rho * rho;
  }
  return 2.0 * k / (1.0 + 2.0 * sum);
}

std::vector<double> welch_bin_correlation(std::span<const double> window, std::size_t hop,
                                          std::size_t segment_count, std::size_t max_bin_offset) {
  checked_window_power(window, hop, segment_count);
  const auto weighted_power = [&](std::size_t bin_offset) {
    double sum = 0.0;
    for (std::size_t m = 0; m < segment_count && m * hop < window.size(); ++m) {
      // Lags ±m: (K − m) segment pairs each; lag 0: K pairs.
      const double pairs = static_cast<double>(segment_count - m) * (m == 0 ? 1.0 : 2.0);
      sum += pairs * lagged_spectral_power(window, m * hop, bin_offset);
    }
    return sum;
  };
  std::vector<double> correlation(max_bin_offset + 1, 1.0);
  const double at_zero = weighted_power(0);
  for (std::size_t d = 1; d <= max_bin_offset; ++d) {
    correlation[d] = weighted_power(d) / at_zero;
  }
  return correlation;
}

}  // namespace ridefit::signal
