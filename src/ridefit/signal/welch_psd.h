#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <span>
#include <vector>

#include "ridefit/signal/detrend.h"

namespace ridefit::signal {

// Segment length: give at most one of segment_length_samples and segment_length_s (seconds
// are rounded to the nearest sample). With neither, the signal is split into 8 segments at the
// requested overlap, L = floor(N / (8 − 7·overlap)), MATLAB pwelch's default.
//
// A segment longer than the signal is an InputError, not clamped: clamping would silently
// coarsen the frequency resolution the caller asked for. The message states the longest
// segment the signal allows.
struct WelchOptions {
  std::size_t segment_length_samples = 0;  // 0 = not given
  double segment_length_s = 0.0;           // 0 = not given
  double overlap_fraction = 0.5;           // in [0, 1); overlap = floor(overlap_fraction·L)
  Detrend detrend = Detrend::kMean;        // applied to every segment before windowing
};

// One-sided power spectral density estimate.
//
// degrees_of_freedom[k] is the equivalent number of degrees of freedom ν of psd[k]: ν·psd/PSD
// is approximately χ²_ν-distributed (see equivalent_dof.h, psd_confidence.h). It assumes the
// true spectrum is locally flat; DC and Nyquist carry half the interior value, and the lowest
// bins, which detrending alters, are not described by it. Averaging (psd_average.h) adds the
// degrees of freedom, smoothing (psd_smoothing.h) raises them.
struct PowerSpectralDensity {
  std::vector<double> frequency_Hz;  // k·fs/L, k = 0 … floor(L/2)
  std::vector<double> psd;           // [signal unit]²/Hz
  double sample_rate_Hz = 0.0;
  double frequency_resolution_Hz = 0.0;  // fs/L
  std::size_t segment_length_samples = 0;
  std::size_t segment_count = 0;           // segments averaged (summed over averaged records)
  std::size_t hop_samples = 0;             // L − overlap: the distance between segment starts
  std::vector<double> degrees_of_freedom;  // per bin, as psd
  std::size_t smoothing_bins = 1;          // moving-average width applied (1 = unsmoothed)
};

// Welch's averaged, modified periodogram of a uniformly sampled signal.
//
// Each segment x_j of length L (hop L − overlap; trailing samples that do not fill a segment
// are dropped) is detrended, multiplied by the periodic Hann window
// w[n] = 0.5 − 0.5·cos(2πn/L), and transformed (Eigen FFT). The estimate is
//
//   P[k] = c_k · mean_j |X_j[k]|² / (fs · Σ w[n]²),
//
// with c_k = 2 for all bins but DC and (for even L) Nyquist, c_k = 1 there: the one-sided
// density. Scaling by fs·Σw² makes Σ_k P[k]·Δf equal the mean of Σ(w·x)²/Σw² over segments,
// i.e. ∫PSD df equals the (detrended) signal's variance (Parseval). The degrees of freedom are
// welch_degrees_of_freedom(window, hop, K), halved at DC and Nyquist.
//
// Throws InputError for a signal under 2 samples, a non-finite sample, sample_rate_Hz ≤ 0 or
// non-finite, overlap outside [0, 1), both or invalid segment lengths, a segment shorter
// than 2 samples or longer than the signal.
PowerSpectralDensity welch_psd(std::span<const double> signal, double sample_rate_Hz,
                               const WelchOptions& options = {});
PowerSpectralDensity welch_psd(const Eigen::Ref<const Eigen::VectorXd>& signal,
                               double sample_rate_Hz, const WelchOptions& options = {});

}  // namespace ridefit::signal
