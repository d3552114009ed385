#pragma once

#include <vector>

namespace ridefit::comfort {

// Likely reactions to a vibration total value in public transport, ISO 2631-1:1997 Annex C.2.3
// (the same zones as seed 001 Table 4).
enum class ComfortReaction {
  kNotUncomfortable,        // a_v < 0.315 m/s²
  kALittleUncomfortable,    // 0.315 … 0.63 m/s²
  kFairlyUncomfortable,     // 0.5 … 1 m/s²
  kUncomfortable,           // 0.8 … 1.6 m/s²
  kVeryUncomfortable,       // 1.25 … 2.5 m/s²
  kExtremelyUncomfortable,  // a_v > 2 m/s²
};

// Every reaction whose range contains a_v, mildest first. The standard's ranges overlap on
// purpose (reactions depend on expectations, duration and activity), so e.g. 0.55 m/s² gives
// {a little, fairly}; at most two apply. Inner ranges are closed at both ends, "less than
// 0.315" is open at 0.315 and "greater than 2" open at 2, as the standard words them. The
// standard says greater than 2 m/s² for extremely uncomfortable; seed 001's Table 4 prints
// 2.5, which we take for a transcription slip (it would leave 2 … 2.5 single-labelled where
// every other boundary region overlaps).
// Throws InputError for a negative or non-finite value.
std::vector<ComfortReaction> comfort_reactions(double total_value_m_per_s2);

// "not uncomfortable", "a little uncomfortable", ... (the standard's words).
const char* to_string(ComfortReaction reaction);

}  // namespace ridefit::comfort
