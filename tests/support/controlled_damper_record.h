#pragma once

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/simulate/strut_test_reference.h"

namespace ridefit::testing {

// A random rig displacement: 40 sines log-spaced over 0.5–20 Hz, amplitudes falling as 1/f (about
// 3 mm RMS), seeded phases.
struct RandomRigMotion {
  std::vector<double> amplitude_m, frequency_Hz, phase_rad;
  explicit RandomRigMotion(unsigned seed, double scale = 1.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
    for (int i = 0; i < 40; ++i) {
      const double f = 0.5 * std::pow(40.0, i / 39.0);
      frequency_Hz.push_back(f);
      amplitude_m.push_back(scale * 0.0012 / f);
      phase_rad.push_back(angle(rng));
    }
  }
  double operator()(double t) const {
    double x = 0.0;
    for (std::size_t i = 0; i < amplitude_m.size(); ++i) {
      x += amplitude_m[i] * std::sin(2.0 * std::numbers::pi * frequency_Hz[i] * t + phase_rad[i]);
    }
    return x;
  }
};

// A command that switches at random between random levels in [0, top] (an MR damper's coil
// current, say), held 0.15–0.5 s each, with 2 ms smooth (tanh) edges so that the reference
// integrator sees a smooth input; seeded.
struct SwitchingCommand {
  std::vector<double> switch_s, level;
  double edge_s = 0.002;
  SwitchingCommand(unsigned seed, double duration_s, double top) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> hold(0.15, 0.5), value(0.0, top);
    level.push_back(value(rng));
    for (double t = hold(rng); t < duration_s; t += hold(rng)) {
      switch_s.push_back(t);
      level.push_back(value(rng));
    }
  }
  double operator()(double t) const {
    double u = level[0];
    for (std::size_t i = 0; i < switch_s.size(); ++i) {
      u += 0.5 * (level[i + 1] - level[i]) * (1.0 + std::tanh((t - switch_s[i]) / edge_s));
    }
    return u;
  }
};

// A rig record of a controlled strut `p` under x(t) and command u(t), sampled at `rate_Hz` over
// [0, duration_s], the force by CVODE at rtol 1e-10 (simulate::reference_strut_test_force).
template <typename Displacement, typename Command>
fitting::HysteresisRecord cvode_controlled_record(const model::StrutTestParameters<double>& p,
                                                  const Displacement& x, const Command& u,
                                                  double duration_s, double rate_Hz,
                                                  const std::string& source = "controlled") {
  fitting::HysteresisRecord r;
  r.source = source;
  const auto samples = static_cast<int>(std::lround(duration_s * rate_Hz));
  for (int k = 0; k <= samples; ++k) {
    r.time_s.push_back(k / rate_Hz);
    r.displacement_m.push_back(x(r.time_s.back()));
    r.command.push_back(u(r.time_s.back()));
  }
  r.command_unit = std::string(1, 'A');
  r.force_N = simulate::reference_strut_test_force(
      r.time_s, [&x](double t) { return x(t); }, p, [&u](double t) { return u(t); });
  return r;
}

// An MR-like strut: passive level c = 800 N·s/m, Fc = 40 N, rising with the current by
// 1500 N·s/m and 180 N per A, the fluid following the coil with τ = 12 ms.
inline model::StrutTestParameters<double> mr_strut() {
  model::StrutTestParameters<double> p{3e6, 40.0, 1.0, 500e3, 800.0, 0, 0, 0};
  p.static_friction_force_N = 40.0;
  p.damping_per_command_Ns_per_m = 1500.0;
  p.coulomb_force_per_command_N = 180.0;
  p.command_lag_s = 0.012;
  return p;
}

}  // namespace ridefit::testing
