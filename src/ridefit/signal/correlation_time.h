#pragma once

#include <cstddef>
#include <span>

namespace ridefit::signal {

// The integrated autocorrelation time of a series in samples: 1 + 2·Σρ_k, summed while the sum
// of each pair of neighbouring lags stays positive (Geyer's initial positive sequence, Geyer
// 1992). 1 for white noise, (1 + ρ)/(1 − ρ) for a first-order autoregression; at least 1, at most
// n. A fit's residuals that are correlated over τ samples carry about n/τ independent values:
// the diagnosis weighs its explanations with it and the fits widen their standard errors by √τ.
double correlation_time_samples(std::span<const double> series);

// The same over consecutive parts of `series` of the given lengths (a fit's records, a spectrum's
// channels), each part's own τ weighted by its length: the parts' joins are no correlation. At
// least 1; parts beyond the series are left out.
double pooled_correlation_time_samples(std::span<const double> series,
                                       std::span<const std::size_t> lengths);

}  // namespace ridefit::signal
