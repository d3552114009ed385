#include "ridefit/simulate/quarter_car_modes.h"

#include <fmt/core.h>

#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/simulate/quarter_car_system.h"

namespace ridefit::simulate {
namespace {

// The road is zero at rest; modes are properties of the unforced system.
class FlatRoad : public road::RoadInput {
 public:
  road::RoadSample at(double) const override { return {}; }
  double duration_s() const override { return 0.0; }
  double max_step_s() const override { return 0.0; }
};

}  // namespace

Eigen::MatrixXd quarter_car_state_matrix(const model::QuarterCar& car) {
  const FlatRoad road;
  const QuarterCarSystem system(car, road);
  const int n = system.size();
  const std::vector<double> rest(static_cast<std::size_t>(n), 0.0);
  Eigen::MatrixXd a(n, n);
  system.jacobian(0.0, rest.data(), a.data());  // Eigen's default layout is column-major
  return a;
}

ModalAnalysis quarter_car_modes(const model::QuarterCar& car) {
  if (car.damper_state() == model::DamperState::kStickSlip) {
    throw InputError(
        "modes are defined for the linear slip and stick models; choose the slip or the stick "
        "state");
  }
  if (!car.is_linear()) {
    throw InputError(fmt::format(
        "modes are defined for a linear model; in {} {} makes it nonlinear (switch the optional "
        "effects off and use compression_to_rebound_ratio 1; in stick the damper's split and "
        "knee do not act)",
        model::to_string(car.damper_state()), car.nonlinearity()));
  }
  const auto& p = car.parameters();
  return analyse_modes(quarter_car_state_matrix(car),
                       {{"body", p.sprung_mass_kg, 0}, {"wheel", p.unsprung_mass_kg, 1}});
}

}  // namespace ridefit::simulate
