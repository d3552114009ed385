#include "ridefit/simulate/quarter_car_system.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "ridefit/simulate/autodiff_jacobian.h"
#include "ridefit/simulate/autodiff_parameters.h"

namespace ridefit::simulate {
namespace {

constexpr int kMax = model::QuarterCar::kMaxStates;

}  // namespace

QuarterCarSystem::QuarterCarSystem(const model::QuarterCar& car, const road::RoadInput& road)
    : car_(car),
      road_(road),
      jacobian_parameters_(
          autodiff_parameters<JacobianScalar>(car.parameters(), car.state_size())) {
  const auto& p = car.parameters();
  const auto state = car.damper_state();
  if (state != model::DamperState::kStick) {
    const bool friction = state == model::DamperState::kStickSlip && p.coulomb_force_N > 0.0;
    if (friction || p.compression_to_rebound_ratio != 1.0) switches_.push_back(Switch::kDamperRate);
    if (p.damper_knee_velocity_m_per_s > 0.0) {
      switches_.push_back(Switch::kKneeRebound);
      switches_.push_back(Switch::kKneeCompression);
    }
  }
  if (p.bump_stop_stiffness_N_per_m > 0.0) switches_.push_back(Switch::kBumpStop);
  if (p.tyre_lift_off) switches_.push_back(Switch::kLiftOff);
}

road::RoadSample QuarterCarSystem::road_at(double t_s) const {
  if (t_s != cached_time_s_) {
    cached_road_ = road_.at(t_s);
    cached_time_s_ = t_s;
  }
  return cached_road_;
}

void QuarterCarSystem::switching(double t_s, const double* x, double* g) const {
  const auto& p = car_.parameters();
  const auto path = p.damper_path(car_.command_at(x, road_at(t_s)));
  const double travel = x[0] - x[1];
  double rate = 0.0;
  if (car_.damper_state() != model::DamperState::kStick) {
    const double friction = car_.damper_state() == model::DamperState::kStickSlip ? x[5] : 0.0;
    rate = path.flow(travel, x[2] - x[3], x[4], friction).damper_rate_m_per_s;
  }
  for (std::size_t j = 0; j < switches_.size(); ++j) {
    switch (switches_[j]) {
      case Switch::kDamperRate:
        g[j] = rate;
        break;
      case Switch::kKneeRebound:
        g[j] = rate - p.damper_knee_velocity_m_per_s;
        break;
      case Switch::kKneeCompression:
        g[j] = rate + p.damper_knee_velocity_m_per_s;
        break;
      case Switch::kBumpStop:
        g[j] = -travel - p.bump_stop_clearance_m;
        break;
      case Switch::kLiftOff: {
        const auto road = road_at(t_s);
        const double tension = p.tyre_stiffness_N_per_m * (x[1] - road.elevation_m) +
                               p.tyre_damping_Ns_per_m * (x[3] - road.rate_m_per_s);
        g[j] = p.static_tyre_load_N() - tension;
        break;
      }
    }
  }
}

bool QuarterCarSystem::derivatives(double t_s, const double* x, double* xdot) const {
  car_.derivatives(x, road_at(t_s), xdot);
  const int n = size();
  return std::all_of(xdot, xdot + n, [](double v) { return std::isfinite(v); });
}

bool QuarterCarSystem::jacobian(double t_s, const double* x, double* jacobian_column_major) const {
  const auto input = road_at(t_s);
  return autodiff_jacobian<kMax>(
      size(), x,
      [&](const JacobianScalar* xa, JacobianScalar* fa) {
        car_.derivatives(xa, input, jacobian_parameters_, fa);
      },
      jacobian_column_major);
}

double QuarterCarSystem::typical_magnitude(int state_index) const {
  // Positions ~1 mm, velocities ~10 mm/s; the damper deflection is often µm in stick;
  // the friction force is judged against Fc; a filtered command (A or V) against 0.1.
  if (state_index == car_.command_state_index()) return 0.1;
  switch (state_index) {
    case 0:
    case 1:
      return 1e-3;
    case 2:
    case 3:
      return 1e-2;
    case 4:
      return 1e-4;
    default:
      return std::max(1.0, car_.parameters().coulomb_force_N);
  }
}

}  // namespace ridefit::simulate
