#pragma once

#include <cstddef>
#include <vector>

namespace ridefit::road {

// What a strut rig can do: its actuator's stroke (± about the mid-position), speed and force, and
// the highest frequency it follows. The defaults are a typical servo-hydraulic damper rig's.
struct RigLimits {
  double stroke_m = 0.05;  // ± this about mid-stroke
  double velocity_m_per_s = 1.5;
  double force_N = 20e3;
  double frequency_Hz = 30.0;

  // InputError naming the field ("rig.stroke_m", …) for a limit that is not positive and finite.
  void validate() const;
};

enum class RigWaveform {
  kSine,      // x = A·sin(2πf·t)
  kTriangle,  // 0 → A → 0 → −A → 0 at a constant speed v, period 4A/v
  kRandom,    // a random-phase multisine: equal amplitudes on every 1/T line in the band
};

// "sine", "triangle", "random".
const char* waveform_name(RigWaveform waveform);

class RigMotion;

// One test for a strut rig: the actuator's displacement over time, sampled as a rig records it.
// Plain fields, checked as a whole by validate() (field names are the test file's keys).
struct RigTest {
  RigWaveform waveform = RigWaveform::kSine;
  double amplitude_m = 0.01;    // sine and triangle: half the stroke
  double frequency_Hz = 1.0;    // sine
  double speed_m_per_s = 0.01;  // triangle
  double rms_m = 0.002;         // random: the displacement's RMS
  double band_low_Hz = 0.5;     // random: the band its lines fill
  double band_high_Hz = 10.0;
  unsigned seed = 1;  // random: the phases
  double duration_s = 10.0;
  double sample_rate_Hz = 1000.0;

  // InputError naming the field and what would be right, for: a value that is not positive and
  // finite; a random band that is empty or holds no 1/duration line; a test shorter than one
  // cycle of its slowest component; fewer than 20 samples per cycle of its fastest; and a motion
  // beyond `limits` (its peak displacement, peak velocity or highest frequency), with the value
  // that would fit.
  void validate(const RigLimits& limits = {}) const;
  // validate() and the motion it checked (one evaluation of the random test's peaks).
  RigMotion motion(const RigLimits& limits = {}) const;
};

// A rig test's displacement, known at every instant (the reference integrator runs on it) and
// at the samples (the record). Built from a test that validate() accepts.
class RigMotion {
 public:
  explicit RigMotion(const RigTest& test);

  double displacement_m(double time_s) const;
  double velocity_m_per_s(double time_s) const;
  // k/fs for k = 0 … N − 1, N = duration × rate (rounded): a whole number of the random test's
  // periods, over which its RMS is exact.
  std::vector<double> sample_times_s() const;
  // The record's motion: the sample times and x, ẋ at them.
  void samples(std::vector<double>& time_s, std::vector<double>& displacement_m,
               std::vector<double>& velocity_m_per_s) const;
  // Peak |x| and |ẋ| (closed forms for sine and triangle; for the random test the largest over a
  // grid four times finer than the samples) and the slowest and fastest frequency (a triangle's
  // fundamental).
  double peak_displacement_m() const;
  double peak_velocity_m_per_s() const;
  double lowest_frequency_Hz() const;
  double highest_frequency_Hz() const;

 private:
  void random_grid(std::size_t n, double dt, std::vector<double>& x, std::vector<double>& v) const;

  RigTest test_;
  std::vector<double> line_Hz_, line_phase_rad_;  // random test
  double line_amplitude_m_ = 0.0;
  double peak_x_ = 0.0, peak_v_ = 0.0;
};

}  // namespace ridefit::road
