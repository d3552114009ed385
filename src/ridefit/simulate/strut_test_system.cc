#include "ridefit/simulate/strut_test_system.h"

#include <ceres/jet.h>

#include <boost/math/interpolators/makima.hpp>

#include <algorithm>
#include <cmath>

#include "ridefit/model/scalar_math.h"

namespace ridefit::simulate {

RigDisplacement::RigDisplacement(std::span<const double> time_s,
                                 std::span<const double> displacement_m,
                                 RigInterpolation interpolation,
                                 std::span<const double> velocity_m_per_s)
    : time_s_(time_s.begin(), time_s.end()),
      displacement_m_(displacement_m.begin(), displacement_m.end()) {
  const std::size_t n = time_s_.size();
  if (n < 5 || interpolation == RigInterpolation::kLinear) return;
  if (velocity_m_per_s.size() == n) {
    slope_m_per_s_.assign(velocity_m_per_s.begin(), velocity_m_per_s.end());
    return;
  }
  const double step = (time_s_.back() - time_s_.front()) / static_cast<double>(n - 1);
  bool uniform = true;
  for (std::size_t k = 1; k < n && uniform; ++k) {
    uniform = std::abs(time_s_[k] - time_s_[k - 1] - step) <= 1e-3 * step;
  }
  if (uniform) {
    spline_.emplace(displacement_m_, time_s_.front(), step);
    return;
  }
  // Uneven steps: a C1 cubic through the samples. Linear pieces put a kink in the motion at every
  // sample, and a 3 kHz record with rounded time stamps then took more steps than the run allows.
  // Boost's modified Akima gives the slopes (its derivative at each sample is that sample's).
  const boost::math::interpolators::makima<std::vector<double>> akima{
      std::vector<double>(time_s_), std::vector<double>(displacement_m_)};
  slope_m_per_s_.resize(n);
  for (std::size_t k = 0; k < n; ++k) slope_m_per_s_[k] = akima.prime(time_s_[k]);
}

std::size_t RigDisplacement::segment_of(double time_s) const {
  const std::size_t last = time_s_.size() - 2;
  std::size_t k = std::min(segment_, last);
  if (time_s >= time_s_[k] && time_s <= time_s_[k + 1]) return k;
  if (time_s > time_s_[k + 1] && k < last && time_s <= time_s_[k + 2]) return segment_ = k + 1;
  if (time_s < time_s_[k] && k > 0 && time_s >= time_s_[k - 1]) return segment_ = k - 1;
  const auto upper = std::upper_bound(time_s_.begin(), time_s_.end(), time_s);
  const auto index = static_cast<std::size_t>(std::max<std::ptrdiff_t>(upper - time_s_.begin(), 1));
  return segment_ = std::min(index - 1, last);
}

double RigDisplacement::hermite_m(double time_s) const {
  const std::size_t k = segment_of(time_s);
  const double h = time_s_[k + 1] - time_s_[k];
  const double s = (time_s - time_s_[k]) / h;
  const double s2 = s * s, s3 = s2 * s;
  return (2.0 * s3 - 3.0 * s2 + 1.0) * displacement_m_[k] +
         (s3 - 2.0 * s2 + s) * h * slope_m_per_s_[k] +
         (3.0 * s2 - 2.0 * s3) * displacement_m_[k + 1] + (s3 - s2) * h * slope_m_per_s_[k + 1];
}

double RigDisplacement::hermite_rate_m_per_s(double time_s) const {
  const std::size_t k = segment_of(time_s);
  const double h = time_s_[k + 1] - time_s_[k];
  const double s = (time_s - time_s_[k]) / h;
  const double s2 = s * s;
  return (6.0 * s2 - 6.0 * s) * (displacement_m_[k] - displacement_m_[k + 1]) / h +
         (3.0 * s2 - 4.0 * s + 1.0) * slope_m_per_s_[k] +
         (3.0 * s2 - 2.0 * s) * slope_m_per_s_[k + 1];
}

double RigDisplacement::at(double time_s) const {
  if (time_s != cached_time_s_) {
    cached_m_ = interpolate(time_s);
    cached_time_s_ = time_s;
  }
  return cached_m_;
}

double RigDisplacement::interpolate(double time_s) const {
  if (exact_m_) return exact_m_(time_s);
  if (spline_) return spline_->value(time_s);
  if (time_s <= time_s_.front()) return displacement_m_.front();
  if (time_s >= time_s_.back()) return displacement_m_.back();
  if (!slope_m_per_s_.empty()) return hermite_m(time_s);
  const auto upper = std::upper_bound(time_s_.begin(), time_s_.end(), time_s);
  const auto k = static_cast<std::size_t>(upper - time_s_.begin());
  const double w = (time_s - time_s_[k - 1]) / (time_s_[k] - time_s_[k - 1]);
  return (1.0 - w) * displacement_m_[k - 1] + w * displacement_m_[k];
}

double RigDisplacement::rate_at(double time_s) const {
  if (time_s != cached_rate_time_s_) {
    cached_rate_m_per_s_ = interpolate_rate(time_s);
    cached_rate_time_s_ = time_s;
  }
  return cached_rate_m_per_s_;
}

double RigDisplacement::interpolate_rate(double time_s) const {
  if (exact_m_) {
    // Central difference of a smooth function: h = 1e-5 s leaves ~1e-10 relative error.
    const double h = 1e-5;
    return (exact_m_(time_s + h) - exact_m_(time_s - h)) / (2.0 * h);
  }
  if (spline_) return spline_->derivative(time_s);
  if (time_s < time_s_.front() || time_s > time_s_.back() || time_s_.size() < 2) return 0.0;
  if (!slope_m_per_s_.empty()) return hermite_rate_m_per_s(time_s);
  auto upper = std::upper_bound(time_s_.begin(), time_s_.end(), time_s);
  if (upper == time_s_.end()) --upper;
  const auto k = static_cast<std::size_t>(upper - time_s_.begin());
  return (displacement_m_[k] - displacement_m_[k - 1]) / (time_s_[k] - time_s_[k - 1]);
}

bool StrutTestSystem::derivatives(double t_s, const double* y, double* ydot) const {
  model::StrutTest::derivatives(y, x_.at(t_s), x_.rate_at(t_s), command_at(t_s), p_, ydot);
  bool finite = true;
  for (int i = 0; i < size(); ++i) finite = finite && std::isfinite(ydot[i]);
  return finite;
}

bool StrutTestSystem::autodiff_jacobian(double t_s, const double* y,
                                        double* jacobian_column_major) const {
  using Jet = ceres::Jet<double, 3>;
  const int n = size();
  Jet yj[3], ydot[3];
  for (int i = 0; i < n; ++i) yj[i] = Jet(y[i], i);
  const model::StrutTestParameters<Jet> p = p_.cast<Jet>();
  model::StrutTest::derivatives(yj, Jet(x_.at(t_s)), Jet(x_.rate_at(t_s)), Jet(command_at(t_s)), p,
                                ydot);
  bool finite = true;
  for (int column = 0; column < n; ++column) {
    for (int row = 0; row < n; ++row) {
      const double value = ydot[row].v[column];
      jacobian_column_major[column * n + row] = value;
      finite = finite && std::isfinite(value);
    }
  }
  return finite;
}

bool StrutTestSystem::jacobian(double t_s, const double* y, double* jacobian_column_major) const {
  const auto path = p_.damper_path();
  if (p_.commanded() || p_.free_play_m > 0.0 || p_.friction_compression_to_rebound_ratio != 1.0 ||
      model::StrutTest::quasi_static(p_) || !path.damper.linear() || !path.top_mount.linear()) {
    return autodiff_jacobian(t_s, y, jacobian_column_major);
  }
  // The partial derivatives written out: this runs once per stage of every tangent replay, where
  // a generic autodiff spent most of its time in exp and log for the Dahl power. Here the top
  // mount is linear and the damper symmetric without a knee (the rest goes to autodiff), so
  // z_c' = v = (k_tm·(x − z_c) − F)/c. A test compares this with autodiff of StrutTest.
  const double c = p_.damping_Ns_per_m;
  const double v = (p_.top_mount_stiffness_N_per_m * (x_.at(t_s) - y[0]) - y[1]) / c;
  const double dv_dz = -p_.top_mount_stiffness_N_per_m / c;
  const double dv_df = -1.0 / c;
  double dr_dz = 0.0, dr_df = 0.0;  // ∂F'/∂z_c, ∂F'/∂F
  if (p_.coulomb_force_N > 0.0) {
    const double sign = v < 0.0 ? -1.0 : 1.0;
    // The sliding level L(v) and dL/dv: Fc and 0 without the Stribeck curve.
    double level = p_.coulomb_force_N, dlevel_dv = 0.0;
    if (p_.stribeck_velocity_m_per_s > 0.0) {
      const double u = v / p_.stribeck_velocity_m_per_s;
      const double excess = (p_.static_friction_force_N - p_.coulomb_force_N) * std::exp(-u * u);
      level = p_.coulomb_force_N + excess;
      dlevel_dv = -2.0 * u / p_.stribeck_velocity_m_per_s * excess;
    }
    const double s = 1.0 - y[1] / level * sign;
    double power = s, slope = 1.0;  // sgn(s)|s|^d and d|s|^(d−1)
    if (p_.dahl_exponent != 1.0) {
      const double magnitude = s == 0.0 ? 0.0 : std::pow(std::abs(s), p_.dahl_exponent);
      power = s < 0.0 ? -magnitude : magnitude;
      slope = s == 0.0 ? model::dahl_power_slope_at_zero(p_.dahl_exponent)
                       : p_.dahl_exponent * magnitude / std::abs(s);
    }
    // s moves with F directly and, through the level, with v: ds/dv = (F·sgn v / L²)·dL/dv.
    const double ds_df = -sign / level;
    const double ds_dv = y[1] * sign / (level * level) * dlevel_dv;
    const double sigma0 = p_.dahl_sigma0_N_per_m;
    dr_dz = sigma0 * (power + v * slope * ds_dv) * dv_dz;
    dr_df = sigma0 * (power * dv_df + v * slope * (ds_df + ds_dv * dv_df));
  }
  jacobian_column_major[0] = dv_dz;
  jacobian_column_major[1] = dr_dz;
  jacobian_column_major[2] = dv_df;
  jacobian_column_major[3] = dr_df;
  return std::isfinite(dr_dz) && std::isfinite(dr_df);
}

double StrutTestSystem::typical_magnitude(int state_index) const {
  if (state_index == 2) return 1.0;  // the command, in A or V
  return state_index == 0 ? 1e-3 : std::max(1.0, p_.coulomb_force_N);
}

void StrutTestSystem::switching(double t_s, const double* y, double* g) const {
  const double rate =
      model::StrutTest::path_state(y, x_.at(t_s), x_.rate_at(t_s), command_at(t_s), p_)
          .rate_m_per_s;
  int i = 0;
  if (has_friction()) g[i++] = rate;
  if (p_.damper_knee_velocity_m_per_s > 0.0) {
    g[i++] = rate - p_.damper_knee_velocity_m_per_s;
    g[i++] = rate + p_.damper_knee_velocity_m_per_s;
  }
  if (p_.free_play_m > 0.0) {
    const double deflection = x_.at(t_s) - y[0];
    const double half = 0.5 * p_.free_play_m;
    const double r = model::kFreePlayRoundingShare * p_.free_play_m;
    g[i++] = deflection - (half - r);
    g[i++] = deflection - (half + r);
    g[i++] = deflection + (half - r);
    g[i++] = deflection + (half + r);
  }
}

}  // namespace ridefit::simulate
