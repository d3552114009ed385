#pragma once

#include <optional>
#include <span>

namespace ridefit::comfort {

// Travel available from static equilibrium to the bump stop (compression) and to the
// rebound stop (extension), both positive [m].
struct RattleSpace {
  double compression_m = 0.0;
  double rebound_m = 0.0;
};

struct SuspensionTravelMetrics {
  double rms_m = 0.0;              // RMS of the travel as given (no mean removed)
  double peak_m = 0.0;             // max |travel|
  double max_compression_m = 0.0;  // max(0, −min travel): deepest compression, ≥ 0
  double max_rebound_m = 0.0;      // max(0, max travel): farthest extension, ≥ 0
  // With a rattle space: the share of samples in [0, 1] beyond it, travel < −compression_m
  // or travel > rebound_m (touching a stop exactly does not count).
  std::optional<double> beyond_rattle_space_share;
};

// Metrics of a suspension travel record, one sample per time step at a uniform rate.
//
// Sign convention: extension (rebound) positive, compression negative, measured from static
// equilibrium, as the quarter car's `travel` channel z_s − z_u
// (simulate::QuarterCarResponse::travel_m).
//
// Throws InputError for an empty record, a non-finite sample, or a rattle space whose sides
// are not positive and finite.
SuspensionTravelMetrics suspension_travel_metrics(
    std::span<const double> travel_m, const std::optional<RattleSpace>& rattle_space = {});

}  // namespace ridefit::comfort
