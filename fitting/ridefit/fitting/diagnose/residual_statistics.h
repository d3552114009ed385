#pragma once

#include <utility>
#include <vector>

namespace ridefit::fitting::diagnose {

// The time-domain checks of a residual the disagreement maps report, for spectra and loops.

// Ljung–Box over lags 1..20 of a residual: the largest |autocorrelation| and the p-value of
// "the residual is white" (a small p: structure the model misses, or coloured noise).
std::pair<double, double> residual_whiteness(const std::vector<double>& residual);

// The RMS of simulated − measured where |measured| is in its top third over that where it is in
// its bottom third: about 1 for an additive error, far above for an error growing with the
// signal; 1 when the bottom third has no residual.
double amplitude_dependence(const std::vector<double>& measured,
                            const std::vector<double>& simulated);

}  // namespace ridefit::fitting::diagnose
