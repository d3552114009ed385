#include "ridefit/signal/welch_psd.h"

#include <fmt/format.h>
#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>

#include "ridefit/common/errors.h"
#include "ridefit/signal/equivalent_dof.h"
#include "ridefit/signal/hann_window.h"

namespace ridefit::signal {
namespace {

std::size_t resolve_segment_length(std::size_t signal_length, double sample_rate_Hz,
                                   const WelchOptions& options) {
  const bool samples_given = options.segment_length_samples > 0;
  const bool seconds_given = options.segment_length_s != 0.0;
  if (samples_given && seconds_given) {
    throw InputError(fmt::format(
        "Welch PSD: both a segment length in samples ({}) and in seconds ({} s) were given; "
        "give only one",
        options.segment_length_samples, options.segment_length_s));
  }
  std::size_t length = 0;
  if (samples_given) {
    length = options.segment_length_samples;
  } else if (seconds_given) {
    if (!std::isfinite(options.segment_length_s) || options.segment_length_s <= 0.0) {
      throw InputError(fmt::format(
          "Welch PSD: segment length {} s is invalid; it must be a positive number of seconds",
          options.segment_length_s));
    }
    const double samples = std::round(options.segment_length_s * sample_rate_Hz);
    // Anything beyond the signal is rejected below; cap first so the cast is defined.
    length = samples > static_cast<double>(signal_length) ? signal_length + 1
                                                          : static_cast<std::size_t>(samples);
  } else {
    // MATLAB pwelch's default: 8 segments at the requested overlap (at least 2 samples).
    length =
        std::max<std::size_t>(2, static_cast<std::size_t>(static_cast<double>(signal_length) /
                                                          (8.0 - 7.0 * options.overlap_fraction)));
  }
  if (length > signal_length) {
    throw InputError(fmt::format(
        "Welch PSD: the segment ({} samples, {} s at {} Hz) is longer than the signal ({} "
        "samples, {} s); use a segment of at most {} samples ({} s)",
        length, static_cast<double>(length) / sample_rate_Hz, sample_rate_Hz, signal_length,
        static_cast<double>(signal_length) / sample_rate_Hz, signal_length,
        static_cast<double>(signal_length) / sample_rate_Hz));
  }
  if (length < 2) {
    throw InputError(fmt::format(
        "Welch PSD: a segment of {} samples is too short; it needs at least 2 samples", length));
  }
  return length;
}

void validate(std::span<const double> signal, double sample_rate_Hz, const WelchOptions& options) {
  if (signal.size() < 2) {
    throw InputError(
        fmt::format("Welch PSD: the signal has {} samples; it needs at least 2", signal.size()));
  }
  if (!std::isfinite(sample_rate_Hz) || sample_rate_Hz <= 0.0) {
    throw InputError(fmt::format(
        "Welch PSD: sample rate {} Hz is invalid; it must be a positive, finite number of Hz",
        sample_rate_Hz));
  }
  if (!(options.overlap_fraction >= 0.0 && options.overlap_fraction < 1.0)) {
    throw InputError(fmt::format(
        "Welch PSD: overlap fraction {} is outside [0, 1); use e.g. 0.5 for 50 % overlap",
        options.overlap_fraction));
  }
  for (std::size_t i = 0; i < signal.size(); ++i) {
    if (!std::isfinite(signal[i])) {
      throw InputError(
          fmt::format("Welch PSD: sample {} (t = {} s) is {}; every sample must be a finite number",
                      i, static_cast<double>(i) / sample_rate_Hz, signal[i]));
    }
  }
}

}  // namespace

PowerSpectralDensity welch_psd(std::span<const double> signal, double sample_rate_Hz,
                               const WelchOptions& options) {
  validate(signal, sample_rate_Hz, options);
  const std::size_t length = resolve_segment_length(signal.size(), sample_rate_Hz, options);
  const auto overlap =
      static_cast<std::size_t>(std::floor(options.overlap_fraction * static_cast<double>(length)));
  const std::size_t hop = length - overlap;  // ≥ 1 because overlap_fraction < 1
  const std::size_t segment_count = (signal.size() - length) / hop + 1;
  const std::size_t bin_count = length / 2 + 1;

  const std::vector<double> window = periodic_hann_window(length);
  double window_power = 0.0;
  for (double w : window) window_power += w * w;

  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  std::vector<double> segment(length);
  std::vector<std::complex<double>> spectrum(bin_count);  // HalfSpectrum: bins 0 … L/2
  std::vector<double> sum_power(bin_count, 0.0);
  for (std::size_t j = 0; j < segment_count; ++j) {
    const double* start = signal.data() + j * hop;
    segment.assign(start, start + length);
    detrend_in_place(segment, options.detrend);
    for (std::size_t i = 0; i < length; ++i) segment[i] *= window[i];
    fft.fwd(spectrum.data(), segment.data(), static_cast<Eigen::Index>(length));
    for (std::size_t k = 0; k < bin_count; ++k) sum_power[k] += std::norm(spectrum[k]);
  }

  PowerSpectralDensity result;
  result.sample_rate_Hz = sample_rate_Hz;
  result.segment_length_samples = length;
  result.segment_count = segment_count;
  result.hop_samples = hop;
  result.frequency_resolution_Hz = sample_rate_Hz / static_cast<double>(length);
  result.frequency_Hz.resize(bin_count);
  result.psd.resize(bin_count);
  const double scale = 1.0 / (sample_rate_Hz * window_power * static_cast<double>(segment_count));
  const double dof = welch_degrees_of_freedom(window, hop, segment_count);
  result.degrees_of_freedom.resize(bin_count);
  const bool has_nyquist_bin = length % 2 == 0;
  for (std::size_t k = 0; k < bin_count; ++k) {
    // DC and Nyquist are real for real input: one squared normal per segment instead of two.
    const bool single = k == 0 || (has_nyquist_bin && k == bin_count - 1);
    result.frequency_Hz[k] = static_cast<double>(k) * result.frequency_resolution_Hz;
    result.psd[k] = (single ? 1.0 : 2.0) * scale * sum_power[k];
    result.degrees_of_freedom[k] = single ? 0.5 * dof : dof;
  }
  return result;
}

PowerSpectralDensity welch_psd(const Eigen::Ref<const Eigen::VectorXd>& signal,
                               double sample_rate_Hz, const WelchOptions& options) {
  return welch_psd(std::span<const double>(signal.data(), static_cast<std::size_t>(signal.size())),
                   sample_rate_Hz, options);
}

}  // namespace ridefit::signal
