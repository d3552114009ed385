#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>
#include <unsupported/Eigen/AutoDiff>
#include <vector>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/simulate/integrator.h"
#include "ridefit/simulate/ode_system.h"

namespace ridefit::testing {

// The rig force of a strut under an analytic displacement x(t), integrated by CVODE at rtol
// 1e-10: data made by another integrator than the one the fits and the strut solver use
// (ridefit's ESDIRK), and without sampling the displacement, so a test that fits or compares
// against it measures the scheme under test.
template <typename Displacement>
std::vector<double> cvode_rig_force(const std::vector<double>& time_s, Displacement x,
                                    const model::StrutTestParameters<double>& p) {
  class Ode : public simulate::OdeSystem {
   public:
    Ode(const model::StrutTestParameters<double>& parameters, const Displacement& displacement)
        : p_(parameters), x_(displacement) {}
    int size() const override { return 2; }
    double max_step_s() const override { return 0.0; }
    bool derivatives(double t, const double* y, double* ydot) const override {
      model::StrutTest::derivatives(y, x_(t), p_, ydot);
      return true;
    }
    bool jacobian(double t, const double* y, double* j) const override {
      using AD = Eigen::AutoDiffScalar<Eigen::Vector2d>;
      auto c = [](double v) { return AD(v, Eigen::Vector2d::Zero()); };
      AD ya[2] = {AD(y[0], 2, 0), AD(y[1], 2, 1)};
      AD f[2];
      const model::StrutTestParameters<AD> q{
          c(p_.dahl_sigma0_N_per_m),         c(p_.coulomb_force_N),  c(p_.dahl_exponent),
          c(p_.top_mount_stiffness_N_per_m), c(p_.damping_Ns_per_m), c(p_.gas_force_N),
          c(p_.gas_stiffness_N_per_m),       c(p_.force_offset_N),   c(p_.static_friction_force_N),
          c(p_.stribeck_velocity_m_per_s)};
      model::StrutTest::derivatives(ya, c(x_(t)), q, f);
      for (int row = 0; row < 2; ++row) {
        for (int col = 0; col < 2; ++col) j[col * 2 + row] = f[row].derivatives()[col];
      }
      return true;
    }
    // With rtol 1e-10: 0.1 nm and 6 nN for a 60 N strut.
    double typical_magnitude(int i) const override {
      return i == 0 ? 1e-3 : std::max(1.0, p_.coulomb_force_N);
    }

   private:
    model::StrutTestParameters<double> p_;
    const Displacement& x_;
  };
  const Ode ode(p, x);
  simulate::IntegratorOptions options;
  options.method = simulate::Method::kCvodeBdf;
  options.relative_tolerance = 1e-10;
  options.max_steps_per_s = 1e7;
  const auto trajectory = simulate::integrate(ode, {x(time_s.front()), 0.0}, time_s, options);
  std::vector<double> force;
  for (std::size_t k = 0; k < time_s.size(); ++k) {
    force.push_back(model::StrutTest::force_N(trajectory.state_at(k), x(time_s[k]), p));
  }
  return force;
}

// The rig tests' multisine: 3, 1.5 and 0.8 mm at 0.7, 2.3 and 6.1 Hz, with optional phases.
struct ThreeSines {
  double phase_rad[3] = {0.0, 0.0, 0.0};
  double operator()(double t) const {
    const double w = 2.0 * 3.14159265358979323846;
    return 0.003 * std::sin(w * 0.7 * t + phase_rad[0]) +
           0.0015 * std::sin(w * 2.3 * t + phase_rad[1]) +
           0.0008 * std::sin(w * 6.1 * t + phase_rad[2]);
  }
};

// A rig record of `p` under x(t) sampled at `rate_Hz` over [0, duration_s], its force by
// cvode_rig_force (noise-free).
template <typename Displacement>
fitting::HysteresisRecord cvode_rig_record(const model::StrutTestParameters<double>& p,
                                           const Displacement& x, double duration_s, double rate_Hz,
                                           const std::string& source) {
  fitting::HysteresisRecord r;
  r.source = source;
  const auto samples = static_cast<int>(std::lround(duration_s * rate_Hz));
  for (int k = 0; k <= samples; ++k) {
    r.time_s.push_back(k / rate_Hz);
    r.displacement_m.push_back(x(r.time_s.back()));
  }
  r.force_N = cvode_rig_force(r.time_s, x, p);
  return r;
}

}  // namespace ridefit::testing
