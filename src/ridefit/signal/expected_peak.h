#pragma once

#include <span>

namespace ridefit::signal {

// Spectral moment m_k = ∫ f^k·S(f) df of a one-sided PSD on increasing frequencies [Hz]
// (trapezoid in ln f, as the log-spaced spectra of the frequency-domain path are sampled).
double spectral_moment(std::span<const double> frequency_Hz, std::span<const double> psd,
                       int order);

// The expected largest |x| of a stationary, zero-mean Gaussian process over `duration_s`, from
// its spectral moments (Davenport 1964): with σ = √m0, the zero up-crossing rate ν0 = √(m2/m0)
// and n = 2·ν0·T excursions (both signs count for |x|),
//   E[max |x|] ≈ σ·(√(2 ln n) + γ/√(2 ln n)),   γ = 0.5772 (Euler–Mascheroni).
// The asymptotic form needs n well above 1; n is clamped at e² (a record of a few cycles),
// where it gives 2.29·σ. What a time-domain peak of the same linear system converges to on
// average; a single record scatters around it by about ±0.3·σ·π/√(12 ln n).
double expected_gaussian_peak(double m0, double m2, double duration_s);

}  // namespace ridefit::signal
