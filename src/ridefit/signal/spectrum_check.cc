#include "ridefit/signal/spectrum_check.h"

#include <fmt/format.h>

#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::signal {

void check_spectrum_band(std::string_view caller, std::span<const double> frequency_Hz,
                         std::span<const double> psd, double low_Hz, double high_Hz) {
  if (frequency_Hz.size() != psd.size()) {
    throw InputError(fmt::format("{}: {} frequencies but {} PSD values; they must pair up", caller,
                                 frequency_Hz.size(), psd.size()));
  }
  if (frequency_Hz.size() < 2) {
    throw InputError(fmt::format("{}: the spectrum has {} points; it needs at least 2", caller,
                                 frequency_Hz.size()));
  }
  for (std::size_t i = 0; i < frequency_Hz.size(); ++i) {
    if (!std::isfinite(frequency_Hz[i]) || (i > 0 && !(frequency_Hz[i] > frequency_Hz[i - 1]))) {
      throw InputError(fmt::format(
          "{}: frequency {} ({} Hz) is not finite or not above the previous one; frequencies "
          "must be finite and strictly increasing",
          caller, i, frequency_Hz[i]));
    }
    if (!std::isfinite(psd[i]) || psd[i] < 0.0) {
      throw InputError(fmt::format(
          "{}: PSD value {} (at {} Hz) is {}; PSD values must be finite and non-negative", caller,
          i, frequency_Hz[i], psd[i]));
    }
  }
  const double first = frequency_Hz.front();
  const double last = frequency_Hz.back();
  const double slack = 1e-9 * std::max(std::abs(first), std::abs(last));
  if (!std::isfinite(low_Hz) || !std::isfinite(high_Hz) || !(low_Hz < high_Hz)) {
    throw InputError(
        fmt::format("{}: band [{}, {}] Hz is invalid; it needs finite edges with low < high",
                    caller, low_Hz, high_Hz));
  }
  if (low_Hz < first - slack || high_Hz > last + slack) {
    throw InputError(fmt::format(
        "{}: band [{}, {}] Hz reaches outside the spectrum [{}, {}] Hz; choose a band inside "
        "it (raise the sample rate for higher frequencies, lengthen segments for lower ones)",
        caller, low_Hz, high_Hz, first, last));
  }
}

void check_psd_statistics(std::string_view caller, std::string_view name,
                          const PowerSpectralDensity& spectrum) {
  const std::size_t n = spectrum.psd.size();
  if (n < 2 || spectrum.frequency_Hz.size() != n || spectrum.degrees_of_freedom.size() != n) {
    throw InputError(fmt::format(
        "{}: {} has {} frequencies, {} PSD values and {} degrees of freedom; they must pair up, "
        "with at least 2 bins (use welch_psd to make a spectrum)",
        caller, name, spectrum.frequency_Hz.size(), n, spectrum.degrees_of_freedom.size()));
  }
  if (!std::isfinite(spectrum.sample_rate_Hz) || !(spectrum.sample_rate_Hz > 0.0)) {
    throw InputError(fmt::format("{}: {} has sample rate {} Hz; it must be positive and finite",
                                 caller, name, spectrum.sample_rate_Hz));
  }
  if (spectrum.segment_length_samples == 0 || spectrum.segment_count == 0 ||
      spectrum.hop_samples == 0 || spectrum.smoothing_bins == 0) {
    throw InputError(fmt::format(
        "{}: {} has segment length {}, segment count {}, hop {} and smoothing width {}; each "
        "must be at least 1",
        caller, name, spectrum.segment_length_samples, spectrum.segment_count, spectrum.hop_samples,
        spectrum.smoothing_bins));
  }
  for (std::size_t k = 0; k < n; ++k) {
    const double p = spectrum.psd[k];
    const double dof = spectrum.degrees_of_freedom[k];
    if (!std::isfinite(p) || p < 0.0 || !std::isfinite(dof) || !(dof > 0.0)) {
      throw InputError(fmt::format(
          "{}: {} bin {} ({} Hz) has PSD {} and {} degrees of freedom; the PSD must be finite "
          "and ≥ 0, the degrees of freedom finite and > 0",
          caller, name, k, spectrum.frequency_Hz[k], p, dof));
    }
  }
}

}  // namespace ridefit::signal
