#include "ridefit/simulate/half_car_system.h"

#include <fmt/core.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "ridefit/simulate/autodiff_jacobian.h"

#include "ridefit/common/errors.h"

namespace ridefit::simulate {
namespace {

constexpr int kMaxStates = 2 * model::kHalfCarDofs + 6;

}  // namespace

AxleRoadInput::AxleRoadInput(const road::RoadInput& road, double rear_delay_s)
    : road_(road), rear_delay_s_(rear_delay_s) {}

model::AxleRoads AxleRoadInput::at(double time_s) const {
  model::AxleRoads roads;
  roads.front = road_.at(time_s);
  if (time_s >= rear_delay_s_) {
    roads.rear = road_.at(time_s - rear_delay_s_);
  } else {
    roads.rear = {road_.at(0.0).elevation_m, 0.0};
  }
  return roads;
}

double rear_delay_s(const road::RoadInput& road, double wheelbase_m,
                    std::optional<double> rear_delay_s, std::string_view name) {
  if (rear_delay_s) {
    if (!(*rear_delay_s >= 0.0) || !std::isfinite(*rear_delay_s)) {
      throw InputError(fmt::format("rear delay {} s: expected a finite delay >= 0", *rear_delay_s));
    }
    return *rear_delay_s;
  }
  const auto speed = road.speed_m_per_s();
  if (!speed) {
    throw InputError(
        fmt::format("this excitation is given over time, not driven at a speed: give the rear "
                    "wheel's delay ({}; 0 for a rig that shakes both axles together)",
                    name));
  }
  return wheelbase_m / *speed;
}

HalfCarSystem::HalfCarSystem(const model::HalfCar& car, const AxleRoadInput& roads)
    : car_(car), roads_(roads) {
  const auto& p = car.parameters();
  int internal = 2 * model::kHalfCarDofs;
  auto add = [&](const model::AxleTopology& top, const auto& axle, double arm, int wheel) {
    const bool split = axle.compression_to_rebound_ratio != 1.0;
    if (top.suspension == model::AxleSuspension::kStrut) {
      const bool friction =
          top.damper_state == model::DamperState::kStickSlip && axle.coulomb_force_N > 0.0;
      if (top.damper_state != model::DamperState::kStick && (friction || split)) {
        switches_.push_back({internal, 0.0, 0});
      }
    } else if (split) {
      switches_.push_back({-1, arm, wheel});
    }
    internal += top.internal_state_count();
    if (car.follows_command(axle) && axle.command_lag_s > 0.0) ++internal;
  };
  add(car.topology().front, p.front, p.front_axle_distance_m, model::kFrontWheel);
  add(car.topology().rear, p.rear, -p.rear_axle_distance_m, model::kRearWheel);
}

void HalfCarSystem::switching(double t_s, const double* x, double* g) const {
  double xdot[kMaxStates];
  bool rates = false;
  for (std::size_t j = 0; j < switches_.size(); ++j) {
    const Switch& s = switches_[j];
    if (s.state >= 0) {
      if (!rates) car_.derivatives(x, roads_.at(t_s), xdot);
      rates = true;
      g[j] = xdot[s.state];
    } else {
      const double* v = x + model::kHalfCarDofs;
      g[j] = v[model::kBodyHeave] + s.arm_m * v[model::kBodyPitch] - v[s.wheel];
    }
  }
}

bool HalfCarSystem::derivatives(double t_s, const double* x, double* xdot) const {
  car_.derivatives(x, roads_.at(t_s), xdot);
  return std::all_of(xdot, xdot + size(), [](double v) { return std::isfinite(v); });
}

bool HalfCarSystem::jacobian(double t_s, const double* x, double* jacobian_column_major) const {
  const auto input = roads_.at(t_s);
  return autodiff_jacobian<kMaxStates>(
      size(), x,
      [&](const auto* xa, auto* fa) {
        using AutoDiff = std::remove_cvref_t<decltype(*xa)>;
        car_.derivatives(xa, input, car_.parameters().template cast<AutoDiff>(), fa);
      },
      jacobian_column_major);
}

double HalfCarSystem::typical_magnitude(int state_index) const {
  // Positions ~1 mm (pitch ~1 mrad), velocities ~10 mm/s; a strut's damper deflection ~0.1 mm,
  // its friction force judged against Fc.
  if (state_index < model::kHalfCarDofs) return 1e-3;
  if (state_index < 2 * model::kHalfCarDofs) return 1e-2;
  const int internal = state_index - 2 * model::kHalfCarDofs;
  const int front = car_.front_state_count();
  const bool is_front = internal < front;
  const int index = is_front ? internal : internal - front;
  const auto& topology = is_front ? car_.topology().front : car_.topology().rear;
  if (index == topology.internal_state_count()) return 0.1;  // a filtered command, A or V
  if (index == 0) return 1e-4;
  const auto& axle = is_front ? car_.parameters().front : car_.parameters().rear;
  return std::max(1.0, axle.coulomb_force_N);
}

}  // namespace ridefit::simulate
