#pragma once

#include <span>
#include <string_view>

namespace ridefit::signal {

// Detrending of a signal or of a segment of it.
enum class Detrend {
  kNone,
  kMean,    // removes the mean (DC would otherwise leak into the low bins)
  kLinear,  // removes the least-squares straight line (drift, integrated signals)
};

// Subtracts the mean or the least-squares line of the samples from them (nothing for kNone).
void detrend_in_place(std::span<double> samples, Detrend detrend);

// "none" | "mean" | "linear".
const char* to_string(Detrend detrend);
// Inverse of to_string; throws InputError naming the accepted words.
Detrend parse_detrend(std::string_view name);

}  // namespace ridefit::signal
