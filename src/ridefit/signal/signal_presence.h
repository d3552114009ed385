#pragma once

#include <span>
#include <string>

namespace ridefit::signal {

// The smallest standard deviation (about the mean) a measured channel in `si_unit` must show to
// carry a signal: 1e-6 m/s^2 for accelerations, 1e-8 m for lengths (road, travel, rod
// displacement), 1e-4 N for forces, 1e-9 of the channel's own largest magnitude for anything
// else; and never below 1e-9 of the channel's largest magnitude, so a constant offset with
// round-off in its last digits still counts as constant.
double no_signal_floor(const std::string& si_unit, std::span<const double> values);

// InputError unless the channel varies by more than no_signal_floor: a channel of zeros or a
// constant (a dead sensor, a logger that wrote its offset) would otherwise give spectra, fits
// and comfort values computed from round-off. The message names `source` (the file) and
// `channel`, and what would be right.
void require_signal(std::span<const double> values, const std::string& source,
                    const std::string& channel, const std::string& si_unit);

}  // namespace ridefit::signal
