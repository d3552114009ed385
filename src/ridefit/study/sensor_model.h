#pragma once

#include <optional>
#include <random>
#include <span>
#include <vector>

namespace ridefit::study {

// An accelerometer on a resilient mount (a panel, a bracket): its absolute acceleration is the
// structure's through the base-excited oscillator's transmissibility
//   H(s) = (ω² + 2ζω·s) / (s² + 2ζω·s + ω²),
// unity below f, a peak of about 1/(2ζ) at f, falling above: a mode no quarter car has.
struct SensorMount {
  double frequency_Hz = 12.0;
  double damping_ratio = 0.05;
};

// What a measuring chain does to a true signal, in this order: the mount (if any), a band limit
// (second-order Butterworth high-pass and low-pass, causal, as analogue anti-alias and AC
// coupling are), and additive Gaussian white noise of `noise_fraction` times the true signal's
// RMS. Used by `ridefit generate-hidden` and the diagnosis tests.
struct SensorModel {
  double noise_fraction = 0.005;
  double high_pass_Hz = 0.1;  // 0 = none
  double low_pass_Hz = 0.0;   // 0 = 0.4 times the sample rate (80 % of Nyquist)
  std::optional<SensorMount> mount;
};

// The measured signal. InputError for corner frequencies that are not inside (0, fs/2) or
// inverted, a negative noise fraction, or a mount frequency outside (0, fs/2).
std::vector<double> measure(std::span<const double> truth, double sample_rate_Hz,
                            const SensorModel& sensor, std::mt19937_64& rng);

}  // namespace ridefit::study
