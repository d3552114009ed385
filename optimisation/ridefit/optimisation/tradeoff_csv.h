#pragma once

#include <filesystem>
#include <vector>

#include "ridefit/optimisation/tradeoff_curve.h"

namespace ridefit::optimisation {

// The trade-off curve as CSV, written atomically, one row per limit: the limit, whether it was
// feasible, the objective and the swept metric reached at the optimum, and the design values;
// every header `name[unit]`, the unit read from the metric's name (study::split_unit_suffix).
void write_tradeoff_csv(const TuningStudy& study, const std::vector<TradeoffPoint>& tradeoff,
                        const std::filesystem::path& path);

}  // namespace ridefit::optimisation
