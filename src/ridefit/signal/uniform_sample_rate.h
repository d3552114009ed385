#pragma once

#include <span>
#include <string>

namespace ridefit::signal {

// The sample rate of a strictly increasing time base that must be uniform, as spectra and
// digital filters assume. Recorders jitter and CSV writers round, so each step may differ from
// the median step by up to `tolerance` (relative, 1 % by default); a larger gap or a dropped
// sample is an InputError naming `source`, the row (rows counted as lines of a CSV file: the
// header is row 1, the first sample row 2) and the median step, with the advice to resample.
// Fewer than 2 samples is an InputError too.
double uniform_sample_rate_Hz(std::span<const double> time_s, const std::string& source,
                              double tolerance = 0.01);

}  // namespace ridefit::signal
