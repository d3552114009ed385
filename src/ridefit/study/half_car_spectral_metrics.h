#pragma once

#include <array>
#include <vector>

#include "ridefit/model/half_car.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/simulate/half_car_state_space.h"
#include "ridefit/study/half_car_metrics.h"

namespace ridefit::study {

// Output PSDs of a linear half car driven over a random road, exactly in the frequency domain:
// with the road's temporal PSD S(f) = G(f/U)/U inside the band's [n_lo·U, n_hi·U] (zero outside,
// as the time-domain profile has no harmonics there), the transfer from the profile to output y
//   H_y(f) = H_y,h_f + jω·H_y,ḣ_f + e^{−jωτ}·(H_y,h_r + jω·H_y,ḣ_r),   τ = wheelbase/U,
// and S_y(f) = |H_y(f)|²·S(f). Frequencies are log-spaced over the band, `points` of them.
struct HalfCarSpectra {
  std::vector<double> frequency_Hz;
  std::array<std::vector<double>, simulate::kHalfCarLinearOutputs> psd;  // unit²/Hz
};

HalfCarSpectra half_car_spectra(const model::HalfCar& car, const road::RoadSpectrum& road,
                                std::size_t points = 1000);

// The ride figures of HalfCarMetrics from those spectra: RMS = sqrt(∫ S_y df) and weighted
// RMS = sqrt(∫ |W(f)|²·S_y df) (trapezoid in ln f, which resolves resonances evenly). The
// stationary values a long time-domain run converges to. std::invalid_argument for a car that
// is not linear.
HalfCarMetrics half_car_spectral_metrics(const model::HalfCar& car, const road::RoadSpectrum& road,
                                         std::size_t points = 1000);

// The same figures from spectra already computed for `parameters` (static loads come from them).
HalfCarMetrics half_car_spectral_metrics(const HalfCarSpectra& spectra,
                                         const model::HalfCarParameters<double>& parameters);

}  // namespace ridefit::study
