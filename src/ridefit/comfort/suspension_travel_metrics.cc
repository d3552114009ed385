#include "ridefit/comfort/suspension_travel_metrics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/signal/sample_check.h"
#include "ridefit/signal/statistics.h"

namespace ridefit::comfort {
namespace {

void check_side(double travel_m, const char* side) {
  if (!std::isfinite(travel_m) || travel_m <= 0.0) {
    throw InputError(fmt::format(
        "suspension travel metrics: rattle space in {} is {} m; it must be positive and "
        "finite (the travel from static equilibrium to the stop)",
        side, travel_m));
  }
}

}  // namespace

SuspensionTravelMetrics suspension_travel_metrics(std::span<const double> travel_m,
                                                  const std::optional<RattleSpace>& rattle_space) {
  signal::check_samples("suspension travel metrics", travel_m, 1);
  SuspensionTravelMetrics result;
  result.rms_m = signal::rms(travel_m);
  const auto [low, high] = std::minmax_element(travel_m.begin(), travel_m.end());
  result.max_compression_m = std::max(0.0, -*low);
  result.max_rebound_m = std::max(0.0, *high);
  result.peak_m = std::max(std::abs(*low), std::abs(*high));
  if (rattle_space) {
    check_side(rattle_space->compression_m, "compression");
    check_side(rattle_space->rebound_m, "rebound");
    const auto beyond = std::count_if(travel_m.begin(), travel_m.end(), [&](double z) {
      return z < -rattle_space->compression_m || z > rattle_space->rebound_m;
    });
    result.beyond_rattle_space_share =
        static_cast<double>(beyond) / static_cast<double>(travel_m.size());
  }
  return result;
}

}  // namespace ridefit::comfort
