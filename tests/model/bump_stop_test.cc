// The progressive bump stop (BumpStop): the law at closed-form points, its smoothness, its Jet
// derivatives, its place in the quarter car's equations, and that it caps the compression of a
// large road input.
#include "ridefit/model/bump_stop.h"

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

TEST(BumpStop, LawAtClosedFormPoints) {
  const BumpStop<double> stop{2e5, 0.02, 2.0};  // k_bs 200 N/mm, c0 20 mm, n 2
  EXPECT_EQ(stop.force_N(0.0), 0.0);
  EXPECT_EQ(stop.force_N(0.02), 0.0);   // contact begins
  EXPECT_EQ(stop.force_N(-0.05), 0.0);  // extension: never
  // c = 2·c0: k_bs·c0 = 4000 N whatever n (the secant stiffness k_bs over the last c0).
  EXPECT_NEAR(stop.force_N(0.04), 4000.0, 1e-9);
  // c = 1.5·c0: 4000·0.5² = 1000 N.
  EXPECT_NEAR(stop.force_N(0.03), 1000.0, 1e-9);
  // n = 1 is a linear stop of rate k_bs: 10 mm beyond contact, 2000 N.
  EXPECT_NEAR((BumpStop<double>{2e5, 0.02, 1.0}.force_N(0.03)), 2000.0, 1e-9);
  // n = 3: 4000·0.5³ = 500 N.
  EXPECT_NEAR((BumpStop<double>{2e5, 0.02, 3.0}.force_N(0.03)), 500.0, 1e-9);
  // C1 for n > 1: the slope starts from 0. Over the first µm the secant is k_bs·Δ/c0 = 10 N/m
  // (against k_bs = 2e5 N/m for n = 1).
  const double h = 1e-6;
  EXPECT_NEAR((stop.force_N(0.02 + h) - stop.force_N(0.02)) / h, 2e5 * (h / 0.02), 1e-6);
  // Monotone in c.
  double previous = 0.0;
  for (int i = 1; i <= 100; ++i) {
    const double f = stop.force_N(0.02 + 1e-4 * i);
    EXPECT_GT(f, previous);
    previous = f;
  }
  EXPECT_FALSE(BumpStop<double>{}.active());
  EXPECT_EQ(BumpStop<double>{}.force_N(1.0), 0.0);
}

TEST(BumpStop, JetDerivativesMatchCentralDifferences) {
  using Jet = ceres::Jet<double, 3>;  // d/dk_bs, d/dc0, d/dn
  const double values[3] = {2e5, 0.02, 2.5};
  for (const double compression : {0.025, 0.04, 0.07}) {
    const BumpStop<Jet> stop{Jet(values[0], 0), Jet(values[1], 1), Jet(values[2], 2)};
    const Jet force = stop.force_N(Jet(compression));
    for (int j = 0; j < 3; ++j) {
      double up[3] = {values[0], values[1], values[2]};
      double down[3] = {values[0], values[1], values[2]};
      const double h = 1e-6 * values[j];
      up[j] += h;
      down[j] -= h;
      const double fd = (BumpStop<double>{up[0], up[1], up[2]}.force_N(compression) -
                         BumpStop<double>{down[0], down[1], down[2]}.force_N(compression)) /
                        (2.0 * h);
      EXPECT_NEAR(force.v[j], fd, 1e-6 * std::max(1.0, std::abs(fd)))
          << "parameter " << j << " at " << compression;
    }
    // ∂F/∂k_bs = F/k_bs.
    EXPECT_NEAR(force.v[0], force.a / values[0], 1e-15);
  }
  // Out of contact nothing depends on the stop.
  const BumpStop<Jet> stop{Jet(values[0], 0), Jet(values[1], 1), Jet(values[2], 2)};
  const Jet free = stop.force_N(Jet(0.01));
  EXPECT_EQ(free.a, 0.0);
  EXPECT_EQ(free.v.norm(), 0.0);
}

QuarterCarParameters<double> with_bump_stop(QuarterCarParameters<double> p) {
  p.bump_stop_stiffness_N_per_m = 2e5;
  p.bump_stop_clearance_m = 0.02;
  p.bump_stop_exponent = 2.0;
  return p;
}

// The stop pushes body and wheel apart: the body gains +F/ms, the wheel −F/mu.
TEST(BumpStop, PushesBodyAndWheelApartInTheQuarterCar) {
  const QuarterCarParameters<double> plain = testing::passat_corner().parameters;
  const QuarterCarParameters<double> p = with_bump_stop(plain);
  for (const DamperState state : {DamperState::kStick, DamperState::kSlip}) {
    double x[6] = {-0.01, 0.02, 0.0, 0.0, 0.0, 0.0};  // compression 30 mm: 1000 N
    double with[6] = {}, without[6] = {};
    QuarterCar(state, p).derivatives(x, {}, with);
    QuarterCar(state, plain).derivatives(x, {}, without);
    EXPECT_NEAR(with[2] - without[2], 1000.0 / p.sprung_mass_kg, 1e-9) << to_string(state);
    EXPECT_NEAR(with[3] - without[3], -1000.0 / p.unsprung_mass_kg, 1e-9);
    // Within the clearance the stop is not there, bit for bit.
    x[0] = -0.005;
    x[1] = 0.01;
    QuarterCar(state, p).derivatives(x, {}, with);
    QuarterCar(state, plain).derivatives(x, {}, without);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(with[i], without[i]);
  }
}

// A 40 mm road sine at the body mode (1.3 Hz) drives the slip Passat corner well past 20 mm of
// compression; the stop caps it and carries the difference.
TEST(BumpStop, CapsThePeakCompressionOnALargeSine) {
  const QuarterCarParameters<double> plain = testing::passat_corner().parameters;
  const testing::SineRoad road(0.04, 1.3, 8.0);
  simulate::SimulationOptions options;
  options.output_rate_Hz = 500.0;
  const auto peak_compression = [&](const QuarterCarParameters<double>& p) {
    const auto r = simulate::simulate(QuarterCar(DamperState::kSlip, p), road, options);
    return -*std::min_element(r.travel_m.begin(), r.travel_m.end());
  };
  const double free = peak_compression(plain);
  const double stopped = peak_compression(with_bump_stop(plain));
  EXPECT_GT(free, 0.04);
  EXPECT_LT(stopped, 0.8 * free);
  EXPECT_GT(stopped, 0.02);  // it does reach the stop
}

}  // namespace
}  // namespace ridefit::model
