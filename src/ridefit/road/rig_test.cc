#include "ridefit/road/rig_test.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <string>

#include "ridefit/common/errors.h"

namespace ridefit::road {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Samples per cycle of the fastest component a record needs to show its shape (and a spline
// through the samples to give its velocity within a fraction of a per cent).
constexpr double kSamplesPerCycle = 20.0;

void require_positive(double value, const char* key, const char* unit) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InputError(fmt::format("{}: {} is not a positive finite number [{}]", key, value, unit));
  }
}

// The random test's lines: every k/T inside [low, high].
std::vector<double> grid_lines(const RigTest& t) {
  std::vector<double> lines;
  const long first =
      std::max(1L, static_cast<long>(std::ceil(t.band_low_Hz * t.duration_s - 1e-9)));
  const long last = static_cast<long>(std::floor(t.band_high_Hz * t.duration_s + 1e-9));
  for (long k = first; k <= last; ++k) lines.push_back(static_cast<double>(k) / t.duration_s);
  return lines;
}

}  // namespace

void RigLimits::validate() const {
  require_positive(stroke_m, "rig.stroke_m", "m");
  require_positive(velocity_m_per_s, "rig.velocity_m_per_s", "m/s");
  require_positive(force_N, "rig.force_N", "N");
  require_positive(frequency_Hz, "rig.frequency_Hz", "Hz");
}

const char* waveform_name(RigWaveform waveform) {
  switch (waveform) {
    case RigWaveform::kSine:
      return "sine";
    case RigWaveform::kTriangle:
      return "triangle";
    case RigWaveform::kRandom:
      return "random";
  }
  return "?";
}

void RigTest::validate(const RigLimits& limits) const { (void)motion(limits); }

RigMotion RigTest::motion(const RigLimits& limits) const {
  limits.validate();
  require_positive(duration_s, "duration_s", "s");
  require_positive(sample_rate_Hz, "sample_rate_Hz", "Hz");
  switch (waveform) {
    case RigWaveform::kSine:
      require_positive(amplitude_m, "amplitude_m", "m");
      require_positive(frequency_Hz, "frequency_Hz", "Hz");
      break;
    case RigWaveform::kTriangle:
      require_positive(amplitude_m, "amplitude_m", "m");
      require_positive(speed_m_per_s, "speed_m_per_s", "m/s");
      break;
    case RigWaveform::kRandom:
      require_positive(rms_m, "rms_m", "m");
      require_positive(band_high_Hz, "band_high_Hz", "Hz");
      if (!(std::isfinite(band_low_Hz) && band_low_Hz >= 0.0 && band_low_Hz < band_high_Hz)) {
        throw InputError(
            fmt::format("band_low_Hz: {} Hz must be at least 0 and below band_high_Hz ({} Hz)",
                        band_low_Hz, band_high_Hz));
      }
      if (grid_lines(*this).empty()) {
        throw InputError(
            fmt::format("band_low_Hz, band_high_Hz: the band {}…{} Hz holds no line of a {} s test "
                        "(lines every "
                        "{:.4g} Hz); widen the band or lengthen duration_s",
                        band_low_Hz, band_high_Hz, duration_s, 1.0 / duration_s));
      }
      break;
  }
  const RigMotion motion(*this);
  const double slowest = motion.lowest_frequency_Hz(), fastest = motion.highest_frequency_Hz();
  if (duration_s * slowest < 1.0 - 1e-9) {
    throw InputError(fmt::format(
        "duration_s: {} s is shorter than one cycle of the test ({:.4g} s at {:.4g} Hz); give at "
        "least {:.4g} s",
        duration_s, 1.0 / slowest, slowest, 1.0 / slowest));
  }
  if (sample_rate_Hz < kSamplesPerCycle * fastest) {
    throw InputError(
        fmt::format("sample_rate_Hz: {} Hz gives {:.3g} samples per cycle at {:.4g} Hz; give at "
                    "least {:.4g} Hz "
                    "({} per cycle)",
                    sample_rate_Hz, sample_rate_Hz / fastest, fastest, kSamplesPerCycle * fastest,
                    kSamplesPerCycle));
  }
  // What each limit allows, in the test's own terms: its size scales x and ẋ alike.
  const char* size_key = waveform == RigWaveform::kRandom ? "rms_m" : "amplitude_m";
  const double size = waveform == RigWaveform::kRandom ? rms_m : amplitude_m;
  if (motion.peak_displacement_m() > limits.stroke_m) {
    throw InputError(fmt::format(
        "{}: the test reaches ±{:.4g} mm, beyond the rig's stroke (±{:.4g} mm, rig.stroke_m); "
        "at most {:.4g} mm fits",
        size_key, 1e3 * motion.peak_displacement_m(), 1e3 * limits.stroke_m,
        1e3 * size * limits.stroke_m / motion.peak_displacement_m()));
  }
  if (motion.peak_velocity_m_per_s() > limits.velocity_m_per_s) {
    const char* key = waveform == RigWaveform::kTriangle ? "speed_m_per_s" : size_key;
    const std::string allowed =
        waveform == RigWaveform::kTriangle
            ? fmt::format("{:.4g} m/s", limits.velocity_m_per_s)
            : fmt::format("{:.4g} mm",
                          1e3 * size * limits.velocity_m_per_s / motion.peak_velocity_m_per_s());
    throw InputError(
        fmt::format("{}: the test moves at up to {:.4g} m/s, beyond the rig's {:.4g} m/s "
                    "(rig.velocity_m_per_s); at most {} fits",
                    key, motion.peak_velocity_m_per_s(), limits.velocity_m_per_s, allowed));
  }
  if (fastest > limits.frequency_Hz * (1.0 + 1e-12)) {
    const char* key = waveform == RigWaveform::kSine     ? "frequency_Hz"
                      : waveform == RigWaveform::kRandom ? "band_high_Hz"
                                                         : "speed_m_per_s";
    throw InputError(
        fmt::format("{}: the test's {} reaches {:.4g} Hz, above the {:.4g} Hz the rig follows "
                    "(rig.frequency_Hz)",
                    key, waveform == RigWaveform::kTriangle ? "fundamental" : "motion", fastest,
                    limits.frequency_Hz));
  }
  return motion;
}

RigMotion::RigMotion(const RigTest& test) : test_(test) {
  switch (test.waveform) {
    case RigWaveform::kSine:
      peak_x_ = test.amplitude_m;
      peak_v_ = kTwoPi * test.frequency_Hz * test.amplitude_m;
      return;
    case RigWaveform::kTriangle:
      peak_x_ = test.amplitude_m;
      peak_v_ = test.speed_m_per_s;
      return;
    case RigWaveform::kRandom:
      break;
  }
  line_Hz_ = grid_lines(test);
  if (line_Hz_.empty()) return;
  std::mt19937_64 rng(test.seed);
  std::uniform_real_distribution<double> angle(0.0, kTwoPi);
  for (std::size_t i = 0; i < line_Hz_.size(); ++i) line_phase_rad_.push_back(angle(rng));
  // Equal amplitudes a on n lines: the mean square over the test's whole periods is n·a²/2.
  line_amplitude_m_ = test.rms_m * std::sqrt(2.0 / static_cast<double>(line_Hz_.size()));
  const std::size_t n =
      static_cast<std::size_t>(std::lround(4.0 * test.duration_s * test.sample_rate_Hz));
  std::vector<double> x, v;
  random_grid(n, test.duration_s / static_cast<double>(n), x, v);
  for (std::size_t k = 0; k < n; ++k) {
    peak_x_ = std::max(peak_x_, std::abs(x[k]));
    peak_v_ = std::max(peak_v_, std::abs(v[k]));
  }
}

// The random test on t = k·dt, k < n: each line's phasor turned by a constant step (no sine per
// line and sample; a 60 s test with 1 800 lines at 4 kHz would take seconds), re-normalised now
// and then against the rounding's drift.
void RigMotion::random_grid(std::size_t n, double dt, std::vector<double>& x,
                            std::vector<double>& v) const {
  x.assign(n, 0.0);
  v.assign(n, 0.0);
  for (std::size_t i = 0; i < line_Hz_.size(); ++i) {
    const double w = kTwoPi * line_Hz_[i];
    const std::complex<double> step = std::polar(1.0, w * dt);
    std::complex<double> z = std::polar(1.0, line_phase_rad_[i]);
    for (std::size_t k = 0; k < n; ++k) {
      if (k % 1024 == 0) z = std::polar(1.0, w * dt * static_cast<double>(k) + line_phase_rad_[i]);
      x[k] += line_amplitude_m_ * z.imag();
      v[k] += line_amplitude_m_ * w * z.real();
      z *= step;
    }
  }
}

void RigMotion::samples(std::vector<double>& time_s, std::vector<double>& displacement_m,
                        std::vector<double>& velocity_m_per_s) const {
  time_s = sample_times_s();
  if (test_.waveform == RigWaveform::kRandom) {
    random_grid(time_s.size(), 1.0 / test_.sample_rate_Hz, displacement_m, velocity_m_per_s);
    return;
  }
  displacement_m.resize(time_s.size());
  velocity_m_per_s.resize(time_s.size());
  for (std::size_t k = 0; k < time_s.size(); ++k) {
    displacement_m[k] = this->displacement_m(time_s[k]);
    velocity_m_per_s[k] = this->velocity_m_per_s(time_s[k]);
  }
}

double RigMotion::displacement_m(double t) const {
  switch (test_.waveform) {
    case RigWaveform::kSine:
      return test_.amplitude_m * std::sin(kTwoPi * test_.frequency_Hz * t);
    case RigWaveform::kTriangle: {
      const double a = test_.amplitude_m, v = test_.speed_m_per_s;
      const double quarter = a / v;
      const double s = t - 4.0 * quarter * std::floor(t / (4.0 * quarter));
      if (s < quarter) return v * s;
      if (s < 3.0 * quarter) return a - v * (s - quarter);
      return -a + v * (s - 3.0 * quarter);
    }
    case RigWaveform::kRandom:
      break;
  }
  double x = 0.0;
  for (std::size_t i = 0; i < line_Hz_.size(); ++i) {
    x += std::sin(kTwoPi * line_Hz_[i] * t + line_phase_rad_[i]);
  }
  return line_amplitude_m_ * x;
}

double RigMotion::velocity_m_per_s(double t) const {
  switch (test_.waveform) {
    case RigWaveform::kSine:
      return kTwoPi * test_.frequency_Hz * test_.amplitude_m *
             std::cos(kTwoPi * test_.frequency_Hz * t);
    case RigWaveform::kTriangle: {
      const double quarter = test_.amplitude_m / test_.speed_m_per_s;
      const double s = t - 4.0 * quarter * std::floor(t / (4.0 * quarter));
      return (s < quarter || s >= 3.0 * quarter) ? test_.speed_m_per_s : -test_.speed_m_per_s;
    }
    case RigWaveform::kRandom:
      break;
  }
  double v = 0.0;
  for (std::size_t i = 0; i < line_Hz_.size(); ++i) {
    v += kTwoPi * line_Hz_[i] * std::cos(kTwoPi * line_Hz_[i] * t + line_phase_rad_[i]);
  }
  return line_amplitude_m_ * v;
}

std::vector<double> RigMotion::sample_times_s() const {
  const long n = std::lround(test_.duration_s * test_.sample_rate_Hz);
  std::vector<double> t(static_cast<std::size_t>(std::max(n, 0L)));
  for (long k = 0; k < n; ++k)
    t[static_cast<std::size_t>(k)] = static_cast<double>(k) / test_.sample_rate_Hz;
  return t;
}

double RigMotion::peak_displacement_m() const { return peak_x_; }
double RigMotion::peak_velocity_m_per_s() const { return peak_v_; }

double RigMotion::lowest_frequency_Hz() const {
  switch (test_.waveform) {
    case RigWaveform::kSine:
      return test_.frequency_Hz;
    case RigWaveform::kTriangle:
      return test_.speed_m_per_s / (4.0 * test_.amplitude_m);
    case RigWaveform::kRandom:
      break;
  }
  return line_Hz_.empty() ? 0.0 : line_Hz_.front();
}

double RigMotion::highest_frequency_Hz() const {
  if (test_.waveform != RigWaveform::kRandom) return lowest_frequency_Hz();
  return line_Hz_.empty() ? 0.0 : line_Hz_.back();
}

}  // namespace ridefit::road
