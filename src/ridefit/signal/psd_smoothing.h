#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "ridefit/signal/welch_psd.h"

namespace ridefit::signal {

// Centred moving average over an odd number M = 2h+1 of bins (seed 000, §3.2: "PSDs are
// smoothed with a moving-average filter … to reduce variance").
//
// Edge treatment: the window shrinks symmetrically, bin k averages bins k−h_k … k+h_k with
// h_k = min(h, k, n−1−k). The first and last bins are therefore kept as they are, and every
// average stays centred on its bin, so a spectrum linear in k is unchanged everywhere (a
// one-sided truncated window would bend it at the ends). In the interior an isolated spike of
// area a is spread evenly over M bins with its area kept.
//
// Near DC a detrended spectrum's nearly empty low bins pull the first h smoothed bins down:
// choose M small against the frequencies of interest.
//
// Throws InputError for an even or zero window, a window wider than the data, or a non-finite
// value. M = 1 returns the values unchanged.
std::vector<double> moving_average(std::span<const double> values, std::size_t window_bins);

// The moving average of a Welch PSD with the degrees of freedom it gains. Bin k's
// (white-noise, locally flat) variance is that of the mean of M_k = 2h_k+1 correlated bins,
// so
//   ν_s[k] = M_k² / Σ_{a,b} corr(|a−b|) / sqrt(ν_a·ν_b),
// with corr the correlation between the estimate's bins (welch_bin_correlation for the Hann
// window, hop and segment count the spectrum carries; after an average, the summed segment
// count is used, which is exact for overlap 0 and close otherwise). The neighbouring Hann bins
// are strongly correlated (corr(1) = 4/9 without overlap), so ν grows by less than M: about
// 0.51·M without overlap and 0.50·M at 50 % for wide windows. The result has smoothing_bins = M.
//
// Throws InputError as moving_average, for a spectrum without statistics (see
// check_psd_statistics) and for one that is already smoothed (smooth once, with the total
// width: the correlations of a smoothed spectrum are no longer those of the window).
PowerSpectralDensity smooth_psd(const PowerSpectralDensity& spectrum, std::size_t window_bins);

}  // namespace ridefit::signal
