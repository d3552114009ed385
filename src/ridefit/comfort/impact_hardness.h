#pragma once

#include <cstddef>
#include <span>

namespace ridefit::comfort {

// Thresholds of impact_hardness, as fractions of the record's peak |a|_max.
struct ImpactHardnessOptions {
  // The onset is the first sample with |a| ≥ onset_fraction·|a|_max. It must lie above the
  // noise of the lead-in before the obstacle (relative to the peak), in (0, 1).
  double onset_fraction = 0.05;
  // A peak must swing by at least δ = prominence_fraction·|a|_max against its neighbouring
  // extrema and reach ±δ, in (0, 1). Wiggles smaller than δ are not peaks.
  double prominence_fraction = 0.1;
};

struct SignalPeak {
  std::size_t index = 0;  // sample index in the record
  double time_s = 0.0;    // index / sample rate, from the record's first sample
  double value = 0.0;     // in the record's unit
};

// The "impact hardness" objective values of a single obstacle (seed 000, Section 4.3 and
// Figure 17), in the record's unit (e.g. m/s², weighted or not).
struct ImpactHardness {
  std::size_t onset_index = 0;
  double onset_time_s = 0.0;
  SignalPeak first_positive_peak;
  SignalPeak first_negative_peak;   // the first negative peak after first_positive_peak
  SignalPeak second_negative_peak;  // the next negative peak after a positive one
  // first_positive_peak.value − first_negative_peak.value (> 0).
  double peak_to_peak = 0.0;
  // RMS of the samples from the onset to the second negative peak, both included.
  double rms = 0.0;
};

// Impact hardness of an acceleration record holding one obstacle passage, starting with a
// quiet lead-in before the obstacle, sampled uniformly at sample_rate_Hz.
//
// Definitions (A = max |a| over the record, δ = prominence_fraction·A):
// - Onset: the first sample i with |a_i| ≥ onset_fraction·A.
// - Extrema: from the onset on, the signal is split into alternating maxima and minima whose
//   swings are at least δ (a zigzag with hysteresis δ): a maximum is the highest sample
//   reached before the signal falls more than δ below it, and a minimum the lowest sample
//   reached before it rises more than δ above it; the first extremum is whichever of the two
//   happens first after the onset (on a plateau, its first sample). An extremum counts only
//   once the swing after it has happened, so the record must continue past the second
//   negative peak by a rise of more than δ.
// - A positive peak is a maximum with value ≥ δ, a negative peak a minimum with value ≤ −δ.
// - First positive peak: the first positive peak at or after the onset; first negative peak:
//   the first negative peak after it; second negative peak: the first negative peak after
//   the first positive peak that follows the first negative peak (so the two negative peaks
//   belong to different negative half-waves).
// - peak_to_peak = first positive − first negative peak value; rms over [onset, second
//   negative peak].
// A record whose first lobe is negative starts its sequence at the first positive lobe.
//
// Throws InputError for fewer than 3 samples, a non-finite sample, a bad sample rate or
// option, a record that is zero everywhere or already at the onset threshold in its first
// sample (no lead-in), and a record without an obstacle response: no first positive, first
// negative or second negative peak (the message says which is missing and after what time).
ImpactHardness impact_hardness(std::span<const double> acceleration, double sample_rate_Hz,
                               const ImpactHardnessOptions& options = {});

}  // namespace ridefit::comfort
