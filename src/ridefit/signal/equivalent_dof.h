#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace ridefit::signal {

// Statistics of Welch's estimate for a locally white spectrum (Welch 1967; Percival & Walden
// 1993, §6.17): K segments of length L = window.size(), `hop` samples apart, each multiplied
// by `window`. Nothing here assumes a particular window or overlap: the correlations are summed
// numerically from the window and the hop.
//
// All three throw InputError for an empty or all-zero window, hop = 0 or segment_count = 0.

// The window's normalised overlap correlation at a shift of D samples,
//   ρ(D) = Σ_n w[n]·w[n+D] / Σ_n w[n]²   (0 for D ≥ L; 1/6 for periodic Hann at D = L/2).
double window_overlap_correlation(std::span<const double> window, std::size_t shift);

// Equivalent degrees of freedom ν of an averaged periodogram bin (interior bins, i.e. neither
// DC nor Nyquist, where the count halves),
//   ν = 2K / (1 + 2·Σ_{m=1}^{K−1} (1 − m/K)·ρ²(m·hop)),
// so that ν·P̂/P is approximately χ²_ν: 2K without overlap; for Hann about 1.89·K at 50 % and
// 1.04·K at 75 % (twice the segments for nearly the same ν).
double welch_degrees_of_freedom(std::span<const double> window, std::size_t hop,
                                std::size_t segment_count);

// Correlation coefficient between the estimate's bins k and k+d, d = 0 … max_bin_offset
// (element 0 is 1), away from DC and Nyquist:
//   corr(d) = Σ_m (K−|m|)·|R(m·hop, d)|² / Σ_m (K−|m|)·|R(m·hop, 0)|²,
//   R(D, d) = Σ_n w[n]·w[n+D]·exp(−2πi·d·n/L),
// the cross-segment terms included. For a Hann window without overlap corr(1) = 4/9,
// corr(2) = 1/36 and corr(d ≥ 3) = 0. Used for the degrees of freedom of a smoothed spectrum.
std::vector<double> welch_bin_correlation(std::span<const double> window, std::size_t hop,
                                          std::size_t segment_count, std::size_t max_bin_offset);

}  // namespace ridefit::signal
