#pragma once

#include <span>

namespace ridefit::signal {

// Root-mean-square of a sampled signal (0 for an empty one).
double rms(std::span<const double> values);

}  // namespace ridefit::signal
