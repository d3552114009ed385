#include "ridefit/simulate/strut_test_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ridefit/simulate/integrator.h"
#include "ridefit/simulate/strut_test_system.h"

namespace ridefit::simulate {
namespace {

// The inertia force of the mass the load cell carries, m·ẍ, from a central second difference of
// the exact displacement (h = 0.1 ms: truncation and rounding both far below a newton).
double inertia_force_N(const model::StrutTestParameters<double>& p, const RigDisplacement& x,
                       double t_s) {
  if (p.moving_mass_kg == 0.0) return 0.0;
  constexpr double h = 1e-4;
  return p.moving_mass_kg * (x.at(t_s + h) - 2.0 * x.at(t_s) + x.at(t_s - h)) / (h * h);
}

// The strut with its load cell's low-pass as extra states s_1 (and s_2 for order 2):
// s_1' = (F − s_1)/τ_s, s_2' = (s_1 − s_2)/τ_s with F the rig force without the offset.
class SensedStrutTest : public OdeSystem {
 public:
  SensedStrutTest(const StrutTestSystem& strut, const model::StrutTestParameters<double>& p,
                  const RigDisplacement& x)
      : strut_(strut),
        p_(p),
        x_(x),
        n_(strut.size()),
        stages_(p.force_sensor_order == 2 ? 2 : 1),
        tau_s_(1.0 / (2.0 * std::numbers::pi * p.force_sensor_cutoff_Hz)) {}
  int size() const override { return n_ + stages_; }
  bool derivatives(double t_s, const double* y, double* ydot) const override {
    if (!strut_.derivatives(t_s, y, ydot)) return false;
    const double force =
        model::StrutTest::force_N(y, x_.at(t_s), x_.rate_at(t_s), strut_.command_at(t_s), p_) -
        p_.force_offset_N + inertia_force_N(p_, x_, t_s);
    ydot[n_] = (force - y[n_]) / tau_s_;
    if (stages_ == 2) ydot[n_ + 1] = (y[n_] - y[n_ + 1]) / tau_s_;
    return true;
  }
  bool jacobian(double t_s, const double* y, double* j) const override {
    const int m = size();
    std::fill(j, j + m * m, 0.0);
    std::vector<double> inner(static_cast<std::size_t>(n_ * n_));
    if (!strut_.jacobian(t_s, y, inner.data())) return false;
    for (int c = 0; c < n_; ++c) {
      for (int r = 0; r < n_; ++r) j[c * m + r] = inner[static_cast<std::size_t>(c * n_ + r)];
    }
    j[0 * m + n_] = -p_.top_mount_stiffness_N_per_m / tau_s_;  // ∂s_1'/∂z_c
    j[n_ * m + n_] = -1.0 / tau_s_;
    if (stages_ == 2) {
      j[n_ * m + n_ + 1] = 1.0 / tau_s_;
      j[(n_ + 1) * m + n_ + 1] = -1.0 / tau_s_;
    }
    return true;
  }
  double typical_magnitude(int i) const override {
    return i < n_ ? strut_.typical_magnitude(i) : 1.0;
  }
  double max_step_s() const override { return 0.0; }
  int switching_count() const override { return strut_.switching_count(); }
  void switching(double t_s, const double* y, double* g) const override {
    strut_.switching(t_s, y, g);
  }

 private:
  const StrutTestSystem& strut_;
  model::StrutTestParameters<double> p_;
  const RigDisplacement& x_;
  int n_;
  int stages_;
  double tau_s_;
};

}  // namespace

std::vector<double> reference_strut_test_force(std::span<const double> time_s,
                                               const std::function<double(double)>& displacement_m,
                                               const model::StrutTestParameters<double>& parameters,
                                               const std::function<double(double)>& command) {
  std::vector<double> force;
  if (time_s.empty()) return force;
  const bool delayed = parameters.force_delay_s > 0.0;
  const bool filtered = parameters.force_sensor_cutoff_Hz > 0.0;
  if (delayed && filtered) {
    throw std::invalid_argument("reference_strut_test_force: a delay or a low-pass, not both");
  }
  const RigDisplacement x(displacement_m);
  const RigDisplacement u(command ? command : [](double) { return 0.0; });
  const StrutTestSystem strut(parameters, x, command ? &u : nullptr);
  const SensedStrutTest sensed(strut, parameters, x);
  const OdeSystem& system = filtered ? static_cast<const OdeSystem&>(sensed) : strut;
  IntegratorOptions options;
  options.method = Method::kCvodeBdf;
  options.relative_tolerance = 1e-10;
  options.max_steps_per_s = 1e7;
  // No step longer than the record's mean sample interval. Inside a free play's slack nothing
  // moves and BDF's steps grew to tens of milliseconds; a step from there across the take-up
  // landed on a spurious root of its implicit equations with the Dahl force far above its level
  // and the damper held still (z_c' = 0, F_f = F_tm), so the "reference" force followed k_tm·x for
  // seconds: 373 N RMS off ESDIRK at rtol 1e-9 on a benchmark record with 0.97 mm of play, where
  // a cap of 2 ms (its sample interval) agrees to 1e-6 N and costs 15 % more steps.
  if (time_s.size() > 1) {
    options.max_step_s = (time_s.back() - time_s.front()) / static_cast<double>(time_s.size() - 1);
  }
  // Delayed: the force at t − δ (the strut at rest before the record starts), from output times
  // shifted by δ. The outputs before t₀ + δ all read the first sample's force.
  const double t0 = time_s.front();
  std::vector<double> times;
  for (double t : time_s) {
    const double shifted = delayed ? t - parameters.force_delay_s : t;
    if (shifted > t0 || times.empty()) times.push_back(std::max(shifted, t0));
  }
  std::vector<double> y0 = {displacement_m(t0), 0.0};
  if (strut.size() == 3) y0.push_back(command(t0));
  const double rest_force = model::StrutTest::force_N(y0.data(), displacement_m(t0), x.rate_at(t0),
                                                      command ? command(t0) : 0.0, parameters) -
                            parameters.force_offset_N + inertia_force_N(parameters, x, t0);
  if (filtered) {
    for (int s = 0; s < (parameters.force_sensor_order == 2 ? 2 : 1); ++s) {
      y0.push_back(rest_force);
    }
  }
  const Trajectory trajectory = integrate(system, y0, times, options);
  const std::size_t skipped = time_s.size() - times.size();
  force.reserve(time_s.size());
  for (std::size_t k = 0; k < time_s.size(); ++k) {
    const std::size_t i = k < skipped ? 0 : k - skipped;
    const double* y = trajectory.state_at(i);
    double physical = 0.0;
    if (filtered) {
      physical = y[strut.size() + (parameters.force_sensor_order == 2 ? 1 : 0)];
    } else {
      physical = model::StrutTest::force_N(y, displacement_m(times[i]), x.rate_at(times[i]),
                                           command ? command(times[i]) : 0.0, parameters) -
                 parameters.force_offset_N + inertia_force_N(parameters, x, times[i]);
    }
    force.push_back(parameters.force_gain * physical + parameters.force_offset_N);
  }
  return force;
}

}  // namespace ridefit::simulate
