#include "ridefit/simulate/quarter_car_system.h"

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <algorithm>
#include <cmath>

namespace ridefit::simulate {
namespace {

constexpr int kMax = model::QuarterCar::kMaxStates;
// Derivative vectors live on the stack: dynamic size, fixed capacity.
using Gradient = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMax, 1>;
using AutoDiff = Eigen::AutoDiffScalar<Gradient>;

}  // namespace

bool QuarterCarSystem::derivatives(double t_s, const double* x, double* xdot) const {
  car_.derivatives(x, road_.at(t_s), xdot);
  const int n = size();
  return std::all_of(xdot, xdot + n, [](double v) { return std::isfinite(v); });
}

bool QuarterCarSystem::jacobian(double t_s, const double* x, double* jacobian_column_major) const {
  const int n = size();
  AutoDiff xa[kMax];
  AutoDiff fa[kMax];
  for (int i = 0; i < n; ++i) {
    xa[i] = AutoDiff(x[i], n, i);
  }
  car_.derivatives(xa, road_.at(t_s), car_.parameters().cast<AutoDiff>(), fa);
  for (int row = 0; row < n; ++row) {
    const Gradient& g = fa[row].derivatives();
    for (int col = 0; col < n; ++col) {
      // A constant output (e.g. zs' = vs has no dependence on most states) may carry an
      // empty derivative vector.
      const double value = g.size() == n ? g[col] : 0.0;
      if (!std::isfinite(value)) return false;
      jacobian_column_major[col * n + row] = value;
    }
  }
  return true;
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
