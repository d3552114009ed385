#include "ridefit/signal/displacement_from_acceleration.h"

#include <fmt/format.h>
#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <bit>
#include <cmath>
#include <complex>
#include <cstddef>
#include <numbers>

#include "ridefit/common/errors.h"
#include "ridefit/signal/sample_check.h"

namespace ridefit::signal {
namespace {

constexpr int kMaxOrder = 16;
// The FFT's length: 2^26 samples keep the transform under 2 GB.
constexpr double kMaxTransformSamples = 0x1.0p26;

// The integral of order `integrations` (1: velocity, 2: displacement) of the acceleration.
std::vector<double> integrate_high_pass(std::span<const double> acceleration, double sample_rate_Hz,
                                        const HighPassIntegrationOptions& options, int integrations,
                                        const char* caller) {
  check_samples(caller, acceleration, 2);
  check_sample_rate(caller, sample_rate_Hz);
  const double cutoff_Hz = options.high_pass_Hz;
  if (!(cutoff_Hz > 0.0) || !(cutoff_Hz < 0.5 * sample_rate_Hz)) {
    throw InputError(fmt::format(
        "{}: high-pass cut-off {} Hz is invalid; it must lie between 0 and half the sample "
        "rate ({} Hz)",
        caller, cutoff_Hz, 0.5 * sample_rate_Hz));
  }
  const int order = options.high_pass_order;
  if (order <= integrations || order > kMaxOrder) {
    throw InputError(fmt::format(
        "{}: high-pass order {} is invalid; it must lie in [{}, {}] so that the integrated "
        "signal's response vanishes at 0 Hz",
        caller, order, integrations + 1, kMaxOrder));
  }

  const std::size_t n = acceleration.size();
  const double padding = std::ceil(2.0 * order * sample_rate_Hz / cutoff_Hz);
  if (!(static_cast<double>(n) + padding <= kMaxTransformSamples)) {
    throw InputError(fmt::format(
        "{}: {} samples plus a padding of 2·order·fs/f_c = {:g} samples exceed the {:g} "
        "samples one transform may hold; raise the cut-off, lower the sample rate or split "
        "the record",
        caller, n, padding, kMaxTransformSamples));
  }
  const std::size_t n_fft = std::bit_ceil(n + static_cast<std::size_t>(padding));
  std::vector<double> signal(n_fft, 0.0);
  std::copy(acceleration.begin(), acceleration.end(), signal.begin());
  detrend_in_place(std::span<double>(signal.data(), n), options.detrend);

  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, signal);  // bins 0 … n_fft/2

  const double bin_Hz = sample_rate_Hz / static_cast<double>(n_fft);
  const double exponent = 2.0 * order;
  spectrum.front() = 0.0;  // DC
  spectrum.back() = 0.0;   // Nyquist (n_fft is even)
  for (std::size_t k = 1; k + 1 < spectrum.size(); ++k) {
    const double f = static_cast<double>(k) * bin_Hz;
    const double gain = 1.0 / std::sqrt(1.0 + std::pow(cutoff_Hz / f, exponent));
    const double omega = 2.0 * std::numbers::pi * f;
    // 1/(jω) = −j/ω; 1/(jω)² = −1/ω².
    spectrum[k] *= integrations == 1 ? std::complex<double>(0.0, -gain / omega)
                                     : std::complex<double>(-gain / (omega * omega), 0.0);
  }
  std::vector<double> result;
  fft.inv(result, spectrum, static_cast<Eigen::Index>(n_fft));
  result.resize(n);
  result.shrink_to_fit();
  return result;
}

}  // namespace

std::vector<double> displacement_from_acceleration(std::span<const double> acceleration,
                                                   double sample_rate_Hz,
                                                   const HighPassIntegrationOptions& options) {
  return integrate_high_pass(acceleration, sample_rate_Hz, options, 2,
                             "displacement from acceleration");
}

std::vector<double> velocity_from_acceleration(std::span<const double> acceleration,
                                               double sample_rate_Hz,
                                               const HighPassIntegrationOptions& options) {
  return integrate_high_pass(acceleration, sample_rate_Hz, options, 1,
                             "velocity from acceleration");
}

}  // namespace ridefit::signal
