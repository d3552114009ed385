#include "ridefit/simulate/strut_test_system.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "ridefit/simulate/autodiff_jacobian.h"

namespace ridefit::simulate {

RigDisplacement::RigDisplacement(std::span<const double> time_s,
                                 std::span<const double> displacement_m,
                                 RigInterpolation interpolation)
    : time_s_(time_s.begin(), time_s.end()),
      displacement_m_(displacement_m.begin(), displacement_m.end()) {
  const std::size_t n = time_s_.size();
  if (n < 5 || interpolation == RigInterpolation::kLinear) return;
  const double step = (time_s_.back() - time_s_.front()) / static_cast<double>(n - 1);
  for (std::size_t k = 1; k < n; ++k) {
    if (std::abs(time_s_[k] - time_s_[k - 1] - step) > 1e-3 * step) return;
  }
  spline_.emplace(displacement_m_, time_s_.front(), step);
}

double RigDisplacement::at(double time_s) const {
  if (spline_) return spline_->value(time_s);
  if (time_s <= time_s_.front()) return displacement_m_.front();
  if (time_s >= time_s_.back()) return displacement_m_.back();
  const auto upper = std::upper_bound(time_s_.begin(), time_s_.end(), time_s);
  const auto k = static_cast<std::size_t>(upper - time_s_.begin());
  const double w = (time_s - time_s_[k - 1]) / (time_s_[k] - time_s_[k - 1]);
  return (1.0 - w) * displacement_m_[k - 1] + w * displacement_m_[k];
}

bool StrutTestSystem::derivatives(double t_s, const double* y, double* ydot) const {
  model::StrutTest::derivatives(y, x_.at(t_s), p_, ydot);
  return std::isfinite(ydot[0]) && std::isfinite(ydot[1]);
}

bool StrutTestSystem::jacobian(double t_s, const double* y, double* jacobian_column_major) const {
  const double x = x_.at(t_s);
  return autodiff_jacobian<2>(
      2, y,
      [&](const auto* ya, auto* fa) {
        using AutoDiff = std::remove_cvref_t<decltype(*ya)>;
        // Constants with sized zero derivatives (autodiff_parameters.h says why).
        auto constant = [](double v) {
          AutoDiff a(v);
          a.derivatives().setZero(2);
          return a;
        };
        const model::StrutTestParameters<AutoDiff> p{
            constant(p_.dahl_sigma0_N_per_m),     constant(p_.coulomb_force_N),
            constant(p_.dahl_exponent),           constant(p_.top_mount_stiffness_N_per_m),
            constant(p_.damping_Ns_per_m),        constant(p_.gas_force_N),
            constant(p_.gas_stiffness_N_per_m),   constant(p_.force_offset_N),
            constant(p_.static_friction_force_N), constant(p_.stribeck_velocity_m_per_s)};
        model::StrutTest::derivatives(ya, constant(x), p, fa);
      },
      jacobian_column_major);
}

double StrutTestSystem::typical_magnitude(int state_index) const {
  return state_index == 0 ? 1e-3 : std::max(1.0, p_.coulomb_force_N);
}

void StrutTestSystem::switching(double t_s, const double* y, double* g) const {
  const auto path = p_.damper_path();
  g[0] = path.damper_rate_m_per_s(path.path_force_N(x_.at(t_s), y[0]), y[1]);
}

}  // namespace ridefit::simulate
