// Linear quarter car without friction: the simulated steady state under sine roads matches
// the analytic frequency response.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <tuple>

#include "ridefit/model/quarter_car.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "support/passat.h"
#include "support/sine_road.h"

namespace ridefit::model {
namespace {

using Complex = std::complex<double>;

// Body acceleration per unit road displacement, from the element equations in the
// frequency domain (unknowns Zs, Zu and, for slip, the damper deflection Zc).
Complex body_acceleration_response(const QuarterCarParameters<double>& p, DamperState state,
                                   double frequency_Hz) {
  const double w = 2.0 * std::numbers::pi * frequency_Hz;
  const Complex jw(0.0, w);
  const double ksp = p.spring_path_stiffness_N_per_m();
  const double ktm = p.top_mount_stiffness_N_per_m;
  const Complex tyre = p.tyre_stiffness_N_per_m + jw * p.tyre_damping_Ns_per_m;
  Eigen::Matrix3cd a = Eigen::Matrix3cd::Zero();
  Eigen::Vector3cd b = Eigen::Vector3cd::Zero();
  // ms·s²·Zs + ksp·(Zs − Zu) + ktm·(Zs − Zu − Zc) = 0
  a(0, 0) = p.sprung_mass_kg * jw * jw + ksp + ktm;
  a(0, 1) = -(ksp + ktm);
  a(0, 2) = -ktm;
  // mu·s²·Zu − ksp·(Zs − Zu) − ktm·(Zs − Zu − Zc) + tyre·Zu = tyre·H
  a(1, 0) = -(ksp + ktm);
  a(1, 1) = p.unsprung_mass_kg * jw * jw + ksp + ktm + tyre;
  a(1, 2) = ktm;
  b(1) = tyre;
  if (state == DamperState::kSlip) {
    // c·s·Zc = ktm·(Zs − Zu − Zc)
    a(2, 0) = -ktm;
    a(2, 1) = ktm;
    a(2, 2) = p.damping_Ns_per_m * jw + ktm;
  } else {
    a(2, 2) = 1.0;  // locked damper: Zc = 0
  }
  const Eigen::Vector3cd z = a.fullPivLu().solve(b);
  return jw * jw * z(0);
}

// Amplitude of the component at `frequency_Hz` by least squares over whole periods.
double amplitude_at(const std::vector<double>& t, const std::vector<double>& y, double frequency_Hz,
                    double from_s) {
  const double w = 2.0 * std::numbers::pi * frequency_Hz;
  double ss = 0, sc = 0, cc = 0, ys = 0, yc = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < from_s) continue;
    const double s = std::sin(w * t[k]), c = std::cos(w * t[k]);
    ss += s * s;
    sc += s * c;
    cc += c * c;
    ys += y[k] * s;
    yc += y[k] * c;
  }
  const double det = ss * cc - sc * sc;
  const double a = (ys * cc - yc * sc) / det;
  const double b = (yc * ss - ys * sc) / det;
  return std::hypot(a, b);
}

class LinearQuarterCarResponse : public ::testing::TestWithParam<std::tuple<DamperState, double>> {
};

TEST_P(LinearQuarterCarResponse, SteadyStateMatchesAnalyticFrequencyResponse) {
  const auto [state, frequency_Hz] = GetParam();
  const auto file = testing::passat_corner();
  const QuarterCar car(state, file.parameters);
  const double amplitude = 1e-3;
  // 12 s of settling (about 11 time constants of the slip body mode; the stick modes are
  // lightly damped, so the frequencies keep clear of them), then 5 s of whole periods.
  const double settle = 12.0;
  const testing::SineRoad road(amplitude, frequency_Hz, settle + 5.0);
  simulate::SimulationOptions options;
  options.output_rate_Hz = 2000.0;
  options.integrator.relative_tolerance = 1e-9;
  const auto response = simulate::simulate(car, road, options);
  const double simulated =
      amplitude_at(response.time_s, response.body_acc_m_per_s2, frequency_Hz, settle);
  const double analytic =
      std::abs(body_acceleration_response(file.parameters, state, frequency_Hz)) * amplitude;
  EXPECT_NEAR(simulated, analytic, 5e-3 * analytic)
      << to_string(state) << " at " << frequency_Hz << " Hz";
}

INSTANTIATE_TEST_SUITE_P(
    SlipAndStick, LinearQuarterCarResponse,
    ::testing::Combine(::testing::Values(DamperState::kSlip, DamperState::kStick),
                       ::testing::Values(1.0, 6.0, 13.0, 30.0)),
    [](const ::testing::TestParamInfo<std::tuple<DamperState, double>>& param_info) {
      return std::string(to_string(std::get<0>(param_info.param))) + "_" +
             std::to_string(static_cast<int>(std::get<1>(param_info.param))) + "Hz";
    });

TEST(LinearQuarterCarResponse, StickSlipWithoutFrictionEqualsSlip) {
  auto file = testing::passat_corner();
  file.parameters.coulomb_force_N = 0.0;
  const testing::SineRoad road(1e-3, 2.0, 4.0);
  simulate::SimulationOptions options;
  const auto slip =
      simulate::simulate(QuarterCar(DamperState::kSlip, file.parameters), road, options);
  const auto stick_slip =
      simulate::simulate(QuarterCar(DamperState::kStickSlip, file.parameters), road, options);
  double max_difference = 0.0, max_value = 0.0;
  for (std::size_t k = 0; k < slip.time_s.size(); ++k) {
    max_difference = std::max(
        max_difference, std::abs(slip.body_acc_m_per_s2[k] - stick_slip.body_acc_m_per_s2[k]));
    max_value = std::max(max_value, std::abs(slip.body_acc_m_per_s2[k]));
  }
  EXPECT_LT(max_difference, 1e-4 * max_value);
  EXPECT_GT(max_value, 0.01);
}

}  // namespace
}  // namespace ridefit::model
