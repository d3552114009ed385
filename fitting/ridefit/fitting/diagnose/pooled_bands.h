#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace ridefit::fitting::diagnose {

// Band tests of a spectral ratio: a consistent deviation of 1–2 dB spread over several Hz is
// not significant in any single bin but is in their mean.
//
// The null hypothesis is that the per-bin log ratio r_k = ln(P̂_sim/P̂_meas) scatters about 0 with
// a variance σ² (log_ratio_variance) and correlation ρ(d) between bins d apart
// (signal::welch_bin_correlation: the Hann window's leakage and the segments' overlap). The mean
// of w adjacent bins then has variance σ²/w² · Σ_i Σ_j ρ(|i − j|): the pooled degrees of freedom
// of the band.
//
// Windows of w = 2, 4, 8, … bins (up to max_width_bins and the range) slide in steps of w/2;
// a window is significant when |mean| / its standard deviation exceeds the normal quantile
// z(1 − α / (2·M)), M the number of windows tested over all widths (Bonferroni: the chance that
// two spectra that agree give any significant window is at most α, whatever the windows'
// correlation).
struct PooledBand {
  std::size_t first = 0;  // bins [first, last) of the ratio given
  std::size_t last = 0;
  double mean_log_ratio = 0.0;  // mean of ln(P_sim/P_meas) over the window
  double z = 0.0;               // the mean over its standard deviation (signed)
};

// The significant windows, in order of width then position. `bin_correlation[d]` is ρ(d)
// (element 0 is 1; offsets beyond it count as uncorrelated). Nothing for fewer than 2 bins.
std::vector<PooledBand> significant_pooled_bands(std::span<const double> log_ratio,
                                                 double bin_variance,
                                                 std::span<const double> bin_correlation,
                                                 double alpha, std::size_t max_width_bins);

// σ² of one bin's log ratio under the null. Two independent Welch estimates with ν degrees of
// freedom give 2·ψ'(ν/2) (ψ' the trigamma function: ln χ²_ν/ν has variance ψ'(ν/2)), whatever
// the spectrum's level. A measurement and a simulation driven by the same road scatter together
// and their ratio far less (only the sensor noise and what the model misses are not shared): that
// scatter is estimated from the ratio itself, from its second differences (which remove a smooth
// trend such as a real deviation), robustly (1.4826·MAD), with Var(Δ²r) = σ²·(6 − 8ρ(1) + 2ρ(2)).
// The smaller of the two is used, but not below `floor_variance` (the integrator's and the
// noise-floor estimate's own accuracy: a ratio smoother than that is not trusted to be).
double log_ratio_variance(std::span<const double> log_ratio, double degrees_of_freedom,
                          std::span<const double> bin_correlation, double floor_variance);

}  // namespace ridefit::fitting::diagnose
