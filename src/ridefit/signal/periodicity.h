#pragma once

#include <span>

namespace ridefit::signal {

// Whether a rig displacement repeats one cycle (a sine or triangle test) rather than a random
// history: at least two complete cycles between upward crossings of its mean, whose durations
// differ by less than 5 % RMS and whose peak-to-peak excursions differ by less than 10 % RMS. A
// random test crosses its mean at irregular intervals and fails both. A displacement loop is
// readable only for the periodic kind.
bool looks_periodic(std::span<const double> time_s, std::span<const double> x);

}  // namespace ridefit::signal
