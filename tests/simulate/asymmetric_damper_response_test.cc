// What a rebound/compression split does to a ride: with less damping in compression than in
// rebound the damper's mean force over a cycle is a tension, which the spring balances by a
// compressed mean travel ("jacking down"). Quarter car and half car over sine roads.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ridefit/io/half_car_file.h"
#include "ridefit/simulate/half_car_simulation.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "support/passat.h"
#include "support/sine_road.h"

namespace ridefit::simulate {
namespace {

double mean_from(const std::vector<double>& x, std::size_t first) {
  double sum = 0.0;
  for (std::size_t i = first; i < x.size(); ++i) sum += x[i];
  return sum / static_cast<double>(x.size() - first);
}

double rms_from(const std::vector<double>& x, std::size_t first) {
  double sum = 0.0;
  for (std::size_t i = first; i < x.size(); ++i) sum += x[i] * x[i];
  return std::sqrt(sum / static_cast<double>(x.size() - first));
}

struct QuarterCarRide {
  double mean_travel_m, mean_damper_force_N, body_acc_rms_m_per_s2;
};

// The Passat corner in slip (no friction, so only the damper is nonlinear) over a 10 mm sine
// at 1.5 Hz, near the body mode: the last 10 of 20 s, a whole number of periods.
QuarterCarRide quarter_car_ride(double ratio) {
  model::QuarterCarParameters<double> p = testing::passat_corner().parameters;
  p.compression_to_rebound_ratio = ratio;
  const model::QuarterCar car(model::DamperState::kSlip, p);
  const testing::SineRoad road(0.01, 1.5, 20.0);
  SimulationOptions options;
  options.output_rate_Hz = 200.0;
  const QuarterCarResponse r = simulate(car, road, options);
  const std::size_t settled = r.time_s.size() / 2;
  return {mean_from(r.travel_m, settled), mean_from(r.damper_force_N, settled),
          rms_from(r.body_acc_m_per_s2, settled)};
}

TEST(AsymmetricDamperResponse, SofterCompressionJacksTheQuarterCarDown) {
  const QuarterCarRide symmetric = quarter_car_ride(1.0);
  const QuarterCarRide split = quarter_car_ride(0.5);
  // Symmetric: the travel oscillates about static equilibrium.
  EXPECT_LT(std::abs(symmetric.mean_travel_m), 2e-5);
  EXPECT_LT(std::abs(symmetric.mean_damper_force_N), 0.5);
  // Compression at half the rebound coefficient: a mean damper tension of about 42 N, held by
  // the coil path (27 990 N/m) 1.5 mm compressed.
  EXPECT_NEAR(split.mean_damper_force_N, 41.8, 1.0);
  EXPECT_NEAR(split.mean_travel_m, -1.50e-3, 0.05e-3);
  const double k_sp = testing::passat_corner().parameters.spring_path_stiffness_N_per_m();
  EXPECT_NEAR(k_sp * split.mean_travel_m + split.mean_damper_force_N, 0.0, 0.5);
  // Near the body mode less damping on average lets the body move more: +6.8 % RMS.
  EXPECT_GT(split.body_acc_rms_m_per_s2, 1.04 * symmetric.body_acc_rms_m_per_s2);
  EXPECT_LT(split.body_acc_rms_m_per_s2, 1.10 * symmetric.body_acc_rms_m_per_s2);
}

// The half car with the split at the front only, both wheels on one 10 mm, 1.5 Hz sine: the
// front jacks down, the rear stays at its static travel (the body's mean forces and moments
// balance only with no mean rear spring force, the seat adding none).
TEST(AsymmetricDamperResponse, SofterFrontCompressionJacksTheFrontDownOnly) {
  const auto file = io::load_half_car(testing::dataset("vehicles/ajayi_half_car.yaml"),
                                      {{"front.compression_to_rebound_ratio", "0.5"}});
  const model::HalfCar car = file.make_model();
  const testing::SineRoad road(0.01, 1.5, 20.0);
  HalfCarSimulationOptions options;
  options.rear_delay_s = 0.0;
  options.output_rate_Hz = 200.0;
  const HalfCarResponse r = simulate(car, road, options);
  const std::size_t settled = r.time_s.size() / 2;
  const double front = mean_from(r.channel(&model::HalfCarOutputs::front_travel_m), settled);
  const double rear = mean_from(r.channel(&model::HalfCarOutputs::rear_travel_m), settled);
  const double damper = mean_from(r.channel(&model::HalfCarOutputs::front_damper_force_N), settled);
  EXPECT_NEAR(front, -1.80e-3, 0.05e-3);  // a mean damper tension of 30 N on 16 812 N/m
  EXPECT_LT(std::abs(rear), 0.02 * std::abs(front));
  EXPECT_NEAR(file.parameters.front.spring_stiffness_N_per_m * front + damper, 0.0, 0.5);
}

}  // namespace
}  // namespace ridefit::simulate
