#pragma once

#include <span>
#include <vector>

namespace ridefit::signal {

// Seed 000's calibration value of strut friction (Section 2.2): half the height of the
// hysteresis loop at zero displacement. Each cycle runs from one upward zero crossing of the
// displacement to the next; the force at its upward and at its downward crossing is
// interpolated linearly between the samples around it, and the cycle's friction is
// |F_up − F_down|/2. The seed averages cycles 2…N (the first starts from rest).
struct HysteresisFriction {
  std::vector<double> per_cycle_N;  // every complete cycle, in order
  double mean_N = 0.0;              // over cycles 2…N
  double standard_deviation_N = 0.0;
  int cycles_used = 0;
};

// InputError for arrays of unequal length, a non-finite value, a displacement that never
// crosses zero both ways, or fewer than 2 complete cycles (then cycles 2…N would be empty).
HysteresisFriction hysteresis_friction(std::span<const double> displacement_m,
                                       std::span<const double> force_N);

}  // namespace ridefit::signal
