// The damper-path top mount stiffer at small amplitude (AmplitudeStiffeningSpring): the law at
// closed-form points, its Jet derivatives, its use in every strut topology, and what it does to
// a ride. Numbers are seed 000's: k_s = 707 N/mm at small amplitude, k_l = 488 N/mm at large.
#include "ridefit/model/amplitude_stiffening_spring.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ridefit/model/quarter_car.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "support/passat.h"
#include "support/sine_road.h"

namespace ridefit::model {
namespace {

constexpr double kLarge = 488000.0;     // N/m
constexpr double kSmall = 707000.0;     // N/m
constexpr double kTransition_m = 2e-4;  // δ0

TEST(AmplitudeStiffeningSpring, LawAtClosedFormPoints) {
  const AmplitudeStiffeningSpring<double> spring{kLarge, kSmall, kTransition_m};
  EXPECT_EQ(spring.force_N(0.0), 0.0);
  // δ = δ0: k_l·δ0 + (k_s − k_l)·δ0·tanh 1 = 97.6 + 43.8·0.76159 = 130.958 N.
  EXPECT_NEAR(spring.force_N(kTransition_m), 97.6 + 43.8 * std::tanh(1.0), 1e-9);
  EXPECT_NEAR(spring.force_N(kTransition_m), 130.9578, 1e-4);
  EXPECT_NEAR(spring.force_N(-kTransition_m), -130.9578, 1e-4);  // odd
  // Far out the extra force saturates at (k_s − k_l)·δ0 = 43.8 N: slope k_l.
  EXPECT_NEAR(spring.force_N(0.01), kLarge * 0.01 + 43.8, 1e-9);
  // Stiffness k_s at zero, k_l far out, in between at δ0: k_l + (k_s − k_l)/cosh²1.
  EXPECT_DOUBLE_EQ(spring.stiffness_at_N_per_m(0.0), kSmall);
  EXPECT_NEAR(spring.stiffness_at_N_per_m(0.01), kLarge, 1e-6);
  EXPECT_NEAR(spring.stiffness_at_N_per_m(kTransition_m),
              kLarge + 219000.0 / std::pow(std::cosh(1.0), 2), 1e-6);
  // Monotone: the slope never drops below k_l.
  double previous = spring.force_N(-0.005);
  for (int i = -499; i <= 500; ++i) {
    const double f = spring.force_N(1e-5 * i);
    EXPECT_GT(f, previous);
    previous = f;
  }
  // Off (δ0 = 0): the linear spring, bit for bit.
  const AmplitudeStiffeningSpring<double> linear{kLarge};
  EXPECT_EQ(linear.force_N(1.234e-4), kLarge * 1.234e-4);
  EXPECT_TRUE(linear.linear());
  EXPECT_FALSE(spring.linear());
}

TEST(AmplitudeStiffeningSpring, JetDerivativesMatchCentralDifferences) {
  using Jet = ceres::Jet<double, 3>;  // d/dk_l, d/dk_s, d/dδ0
  for (const double deflection : {5e-5, -3e-4, 1.5e-3}) {
    const AmplitudeStiffeningSpring<Jet> spring{Jet(kLarge, 0), Jet(kSmall, 1),
                                                Jet(kTransition_m, 2)};
    const Jet force = spring.force_N(Jet(deflection));
    const double values[3] = {kLarge, kSmall, kTransition_m};
    for (int j = 0; j < 3; ++j) {
      double up[3] = {values[0], values[1], values[2]};
      double down[3] = {values[0], values[1], values[2]};
      const double h = 1e-6 * values[j];
      up[j] += h;
      down[j] -= h;
      const double fd =
          (AmplitudeStiffeningSpring<double>{up[0], up[1], up[2]}.force_N(deflection) -
           AmplitudeStiffeningSpring<double>{down[0], down[1], down[2]}.force_N(deflection)) /
          (2.0 * h);
      EXPECT_NEAR(force.v[j], fd, 1e-6 * std::max(1.0, std::abs(fd)))
          << "parameter " << j << " at " << deflection;
    }
    // Closed forms: ∂F/∂k_s = δ0·tanh(δ/δ0), ∂F/∂k_l = δ − δ0·tanh(δ/δ0).
    const double t = kTransition_m * std::tanh(deflection / kTransition_m);
    EXPECT_NEAR(force.v[1], t, 1e-15);
    EXPECT_NEAR(force.v[0], deflection - t, 1e-15);
  }
}

QuarterCarParameters<double> stiffening_passat() {
  QuarterCarParameters<double> p = testing::passat_corner().parameters;
  p.top_mount_small_amplitude_stiffness_N_per_m = kSmall;
  p.top_mount_transition_deflection_m = kTransition_m;
  return p;
}

// Every topology runs its path force through the nonlinear law, and the damper rate stays the
// explicit (F_path − F_f)/c.
TEST(AmplitudeStiffeningSpring, EveryStrutTopologyUsesIt) {
  const QuarterCarParameters<double> p = stiffening_passat();
  const AmplitudeStiffeningSpring<double> spring{kLarge, kSmall, kTransition_m};
  const double x[6] = {3e-4, 1e-4, 0.0, 0.0, 5e-5, 10.0};
  const double travel = 2e-4;
  const road::RoadSample road{};
  double xdot[6] = {};
  const double k_sp = p.spring_path_stiffness_N_per_m();
  // Stick: the top mount deflects by the travel.
  QuarterCar(DamperState::kStick, p).derivatives(x, road, xdot);
  EXPECT_DOUBLE_EQ(xdot[2], -(k_sp * travel + spring.force_N(travel)) / p.sprung_mass_kg);
  EXPECT_DOUBLE_EQ(QuarterCar(DamperState::kStick, p).outputs(x, road).friction_force_N,
                   spring.force_N(travel));
  // Slip and stick/slip: by z − z_c.
  const double path = spring.force_N(travel - x[4]);
  QuarterCar(DamperState::kSlip, p).derivatives(x, road, xdot);
  EXPECT_DOUBLE_EQ(xdot[4], path / p.damping_Ns_per_m);
  EXPECT_DOUBLE_EQ(xdot[2], -(k_sp * travel + path) / p.sprung_mass_kg);
  QuarterCar(DamperState::kStickSlip, p).derivatives(x, road, xdot);
  EXPECT_DOUBLE_EQ(xdot[4], (path - x[5]) / p.damping_Ns_per_m);
  EXPECT_DOUBLE_EQ(xdot[3],
                   (k_sp * travel + path - p.tyre_stiffness_N_per_m * x[1]) / p.unsprung_mass_kg);
  // At a 150 µm deflection the path carries 16 % more than the linear 488 N/mm would.
  EXPECT_GT(path, 1.16 * kLarge * (travel - x[4]));
}

// The peak path force over the peak top-mount deflection of the stick quarter car (the top mount
// alone carries the damper path): the effective stiffness a test would measure.
double effective_top_mount_stiffness(const QuarterCarParameters<double>& p, double amplitude_m) {
  const QuarterCar car(DamperState::kStick, p);
  const testing::SineRoad road(amplitude_m, 1.0, 4.0);
  simulate::SimulationOptions options;
  options.output_rate_Hz = 500.0;
  const simulate::QuarterCarResponse r = simulate::simulate(car, road, options);
  double force = 0.0, deflection = 0.0;
  for (std::size_t k = r.time_s.size() / 2; k < r.time_s.size(); ++k) {
    force = std::max(force, std::abs(r.friction_force_N[k]));
    deflection = std::max(deflection, std::abs(r.top_mount_deflection_m[k]));
  }
  return force / deflection;
}

// Seed 000, Section 4.2.2: the top mount looks stiffer at small amplitude. Over a 0.2 mm road
// sine the stick car's top mount shows close to k_s; over a 20 mm sine close to k_l; without the
// effect k_l at both.
TEST(AmplitudeStiffeningSpring, SmallRoadAmplitudesSeeAStifferTopMount) {
  const QuarterCarParameters<double> linear = testing::passat_corner().parameters;
  EXPECT_NEAR(effective_top_mount_stiffness(linear, 2e-4), kLarge, 1e-6 * kLarge);
  EXPECT_NEAR(effective_top_mount_stiffness(linear, 2e-2), kLarge, 1e-6 * kLarge);
  const double small = effective_top_mount_stiffness(stiffening_passat(), 2e-4);
  const double large = effective_top_mount_stiffness(stiffening_passat(), 2e-2);
  EXPECT_GT(small, 0.9 * kSmall);
  EXPECT_LE(small, kSmall);
  EXPECT_LT(large, 1.1 * kLarge);
  EXPECT_GT(large, kLarge);
}

}  // namespace
}  // namespace ridefit::model
