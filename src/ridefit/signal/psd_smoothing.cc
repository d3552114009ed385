#include "ridefit/signal/psd_smoothing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/signal/equivalent_dof.h"
#include "ridefit/signal/hann_window.h"
#include "ridefit/signal/spectrum_check.h"

namespace ridefit::signal {
namespace {

// Half-width of bin k's window: min(h, k, n−1−k).
std::size_t half_width(std::size_t k, std::size_t n, std::size_t half) {
  return std::min({half, k, n - 1 - k});
}

void check_window(std::size_t window_bins, std::size_t bins) {
  if (window_bins % 2 == 0) {
    throw InputError(fmt::format(
        "PSD smoothing: a window of {} bins is invalid; it must be an odd number ≥ 1 so that it "
        "centres on each bin (e.g. {})",
        window_bins, window_bins + 1));
  }
  if (window_bins > bins) {
    throw InputError(fmt::format(
        "PSD smoothing: a window of {} bins is wider than the {} values it smooths; use at most "
        "{}",
        window_bins, bins, bins % 2 == 1 ? bins : bins - 1));
  }
}

}  // namespace

std::vector<double> moving_average(std::span<const double> values, std::size_t window_bins) {
  check_window(window_bins, values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (!std::isfinite(values[k])) {
      throw InputError(fmt::format(
          "PSD smoothing: value {} is {}; every value must be a finite number", k, values[k]));
    }
  }
  const std::size_t n = values.size();
  const std::size_t half = window_bins / 2;
  std::vector<double> smoothed(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t h = half_width(k, n, half);
    double sum = 0.0;
    for (std::size_t i = k - h; i <= k + h; ++i) sum += values[i];
    smoothed[k] = sum / static_cast<double>(2 * h + 1);
  }
  return smoothed;
}

PowerSpectralDensity smooth_psd(const PowerSpectralDensity& spectrum, std::size_t window_bins) {
  check_psd_statistics("PSD smoothing", "the spectrum", spectrum);
  if (spectrum.smoothing_bins != 1) {
    throw InputError(fmt::format(
        "PSD smoothing: the spectrum is already smoothed over {} bins; smooth the unsmoothed "
        "spectrum once, with the total width",
        spectrum.smoothing_bins));
  }
  PowerSpectralDensity result = spectrum;
  result.psd = moving_average(spectrum.psd, window_bins);
  result.smoothing_bins = window_bins;
  if (window_bins == 1) return result;

  const std::vector<double> correlation =
      welch_bin_correlation(periodic_hann_window(spectrum.segment_length_samples),
                            spectrum.hop_samples, spectrum.segment_count, window_bins - 1);
  const std::size_t n = spectrum.psd.size();
  const std::size_t half = window_bins / 2;
  const std::vector<double>& dof = spectrum.degrees_of_freedom;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t h = half_width(k, n, half);
    double sum = 0.0;
    for (std::size_t a = k - h; a <= k + h; ++a) {
      for (std::size_t b = k - h; b <= k + h; ++b) {
        sum += correlation[a > b ? a - b : b - a] / std::sqrt(dof[a] * dof[b]);
      }
    }
    const double count = static_cast<double>(2 * h + 1);
    result.degrees_of_freedom[k] = count * count / sum;
  }
  return result;
}

}  // namespace ridefit::signal
