#pragma once

#include "ridefit/road/road_input.h"

namespace ridefit::road {

// Parameters of a logarithmic sine sweep (seed 000, Section 3.2: 0.1–30 Hz, initial
// amplitude 2 mm or 10 mm, amplitude falling logarithmically). Field names are the YAML keys.
struct LogSweepParameters {
  double start_frequency_Hz = 0.1;    // f0
  double end_frequency_Hz = 30.0;     // f1
  double initial_amplitude_m = 0.01;  // A0
  double end_amplitude_m = 1e-4;      // A1; the seed's signals use A1 = A0/100
  double duration_s = 60.0;           // T

  // Throws InputError naming the field (as a YAML key) of the first invalid value: both
  // frequencies in (0, 500] Hz, amplitudes in (0, 1] m, 1 ms <= T and at most 2e7 steps of
  // max_step_s() (road_limits.h).
  void validate() const;
};

// h(t) = A(t)·sin φ(t) on 0 <= t <= T, with r = f1/f0:
//
//   f(t) = f0·r^(t/T)                         instantaneous frequency (exponential in time)
//   φ(t) = 2π·f0·T/ln r·(r^(t/T) − 1)         phase, φ' = 2π f(t), φ(0) = 0
//   A(t) = A0·(A1/A0)^(t/T)                   amplitude, exponential in time
//   dh/dt = A(t)·[ln(A1/A0)/T·sin φ + 2π f(t)·cos φ]   (analytic)
//
// Both f and A are exponential in time, so log A falls linearly with log f:
// A = A0·(f/f0)^p with p = ln(A1/A0)/ln(f1/f0) (p = ln 0.01/ln 300 = −0.807 for the seed's
// sweeps), the "amplitude decreasing logarithmically" of seed 000. Each frequency decade
// takes the same time, T/log10(r). For f1 = f0 the phase is 2π f0 t.
//
// Before t = 0 the road is flat (h = 0, dh/dt = 0): the car starts at rest and h is
// continuous at t = 0, while dh/dt steps from 0 to 2π·f0·A0 (6.3 mm/s for 10 mm at
// 0.1 Hz), a tiny kick that a start from rest cannot avoid with a sine. After T the same
// law continues (smooth), so an integrator that steps a little past T sees no jump.
class LogSweep : public RoadInput {
 public:
  explicit LogSweep(const LogSweepParameters& parameters);

  RoadSample at(double time_s) const override;
  double duration_s() const override { return parameters_.duration_s; }
  // A quarter of the shortest period, 0.25/max(f0, f1).
  double max_step_s() const override;

  double instantaneous_frequency_Hz(double time_s) const;
  double amplitude_m(double time_s) const;
  double phase_rad(double time_s) const;
  const LogSweepParameters& parameters() const { return parameters_; }

 private:
  LogSweepParameters parameters_;
  double frequency_log_rate_per_s_;  // ln(f1/f0)/T
  double amplitude_log_rate_per_s_;  // ln(A1/A0)/T
};

}  // namespace ridefit::road
