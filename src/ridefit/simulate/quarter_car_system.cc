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

bool QuarterCarSystem::derivatives(double t_s, const double* x, double* xdot) const {
  car_.derivatives(x, road_.at(t_s), xdot);
  const int n = size();
  return std::all_of(xdot, xdot + n, [](double v) { return std::isfinite(v); });
}

bool QuarterCarSystem::jacobian(double t_s, const double* x, double* jacobian_column_major) const {
  const auto input = road_.at(t_s);
  return autodiff_jacobian<kMax>(
      size(), x,
      [&](const auto* xa, auto* fa) {
        using AutoDiff = std::remove_cvref_t<decltype(*xa)>;
        car_.derivatives(xa, input, autodiff_parameters<AutoDiff>(car_.parameters(), size()), fa);
      },
      jacobian_column_major);
}

double QuarterCarSystem::typical_magnitude(int state_index) const {
  // Positions ~1 mm, velocities ~10 mm/s; the damper deflection is often µm in stick;
  // the friction force is judged against Fc.
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
