#pragma once

#include <cstddef>

#include "ridefit/model/quarter_car.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/study/quarter_car_metrics.h"

namespace ridefit::study {

// QuarterCarMetrics of a linear (slip or stick) quarter car on a random road, exactly in the
// frequency domain: with the road's temporal PSD S(f) = G(f/U)/U over the band [n_lo·U, n_hi·U],
// S_y(f) = |H_y,h(f) + jω·H_y,ḣ(f)|²·S(f) at `points` log-spaced frequencies; RMS = √∫S_y df,
// Wk-weighted RMS = √∫|Wk|²·S_y df; the peak travel is the expected largest |travel| over the
// road's duration less `settle_s` (signal/expected_peak.h); stuck share 0. The stationary values
// a long simulation converges to. std::invalid_argument for a car that is not linear.
QuarterCarMetrics quarter_car_spectral_metrics(const model::QuarterCar& car,
                                               const road::RoadSpectrum& road,
                                               std::size_t points = 1000, double settle_s = 0.0);

}  // namespace ridefit::study
