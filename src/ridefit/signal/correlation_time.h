#pragma once

#include <span>

namespace ridefit::signal {

// The integrated autocorrelation time of a series in samples: 1 + 2·Σρ_k, summed while the sum
// of each pair of neighbouring lags stays positive (Geyer's initial positive sequence, Geyer
// 1992). 1 for white noise, (1 + ρ)/(1 − ρ) for a first-order autoregression; at least 1, at most
// n. A fit's residuals that are correlated over τ samples carry about n/τ independent values:
// the diagnosis weighs its explanations with it and the fits widen their standard errors by √τ.
double correlation_time_samples(std::span<const double> series);

}  // namespace ridefit::signal
