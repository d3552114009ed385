#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/model/quarter_car.h"

namespace ridefit::synthetic {

// The half-widths of the errors a data sheet's values carry, as shares of each value (issue "A
// diagnosis that holds when the engineer's model is off"): masses ±3 %, tyre and spring rates
// ±8 %, damping ±12 %, top mount ±15 %, Coulomb force ±25 % (the diagnosis's
// datasheet_tolerances()); σ0 (dahl_sigma0_N_per_m) within a factor 2 either way.
const std::map<std::string, double>& datasheet_error_widths();

// `car`'s values as an engineer's data sheet gives them: each key of datasheet_error_widths()
// times 1 + U(−w, w), σ0 times 2^U(−1, 1), from std::mt19937_64(seed) in the keys' order (then
// σ0). A value of 0 (no friction) stays 0, a rigid top mount (≥ 1e9 N/m) rigid. Nothing is
// tuned to a draw: a spec or a test names its
// seed and takes what comes.
std::vector<std::pair<std::string, double>> datasheet_values(const model::QuarterCar& car,
                                                             std::uint64_t seed);

}  // namespace ridefit::synthetic
