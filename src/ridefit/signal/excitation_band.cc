#include "ridefit/signal/excitation_band.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/signal/welch_psd.h"

namespace ridefit::signal {

namespace {

// The largest unbiased autocorrelation of x (mean removed) beyond its first zero crossing, for
// lags up to n/2, by FFT (zero-padded against wrap-around).
double repeat_correlation(std::span<const double> x) {
  const std::size_t n = x.size();
  double mean = 0.0;
  for (double v : x) mean += v / static_cast<double>(n);
  std::size_t size = 1;
  while (size < 2 * n) size *= 2;
  std::vector<double> padded(size, 0.0);
  for (std::size_t k = 0; k < n; ++k) padded[k] = x[k] - mean;
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, padded);
  for (auto& c : spectrum) c = std::norm(c);
  std::vector<double> r;
  fft.inv(r, spectrum);
  if (!(r[0] > 0.0)) return 0.0;
  std::size_t lag = 1;
  while (lag < n / 2 && r[lag] > 0.0) ++lag;
  double largest = 0.0;
  for (; lag <= n / 2; ++lag) {
    const double unbiased = r[lag] / r[0] * static_cast<double>(n) / static_cast<double>(n - lag);
    largest = std::max(largest, unbiased);
  }
  return largest;
}

}  // namespace

ExcitationBand excitation_band(std::span<const double> input, std::span<const double> residual,
                               double sample_rate_Hz, double input_share) {
  if (input.size() != residual.size()) {
    throw InputError(
        fmt::format("excitation band: input has {} samples, residual {}; expected "
                    "the same samples",
                    input.size(), residual.size()));
  }
  if (input.size() < 128) {
    throw InputError(fmt::format(
        "excitation band: {} samples; expected at least 128 for two spectra", input.size()));
  }
  if (!(input_share > 0.0 && input_share <= 1.0)) {
    throw InputError(
        fmt::format("excitation band: input share {}; expected a share in (0, 1]", input_share));
  }
  WelchOptions options;
  options.segment_length_samples = std::max<std::size_t>(64, input.size() / 8);
  const PowerSpectralDensity in = welch_psd(input, sample_rate_Hz, options);
  const PowerSpectralDensity out = welch_psd(residual, sample_rate_Hz, options);
  double total_in = 0.0, total_out = 0.0;
  for (std::size_t k = 0; k < in.psd.size(); ++k) {
    total_in += in.psd[k];
    total_out += out.psd[k];
  }
  ExcitationBand band;
  band.band_Hz = in.frequency_Hz.back();
  double below_in = 0.0, below_out = 0.0;
  for (std::size_t k = 0; k < in.psd.size(); ++k) {
    below_in += in.psd[k];
    below_out += out.psd[k];
    if (below_in >= input_share * total_in) {
      band.band_Hz = in.frequency_Hz[k];
      break;
    }
  }
  band.residual_in_band_share = total_out > 0.0 ? std::min(below_out / total_out, 1.0) : 1.0;
  band.repeat_correlation = repeat_correlation(input);
  return band;
}

}  // namespace ridefit::signal
