// The half car over roads in the time domain: delay, symmetry, semi-active control, friction.
#include "ridefit/simulate/half_car_simulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/io/half_car_file.h"
#include "ridefit/road/cleat.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/signal/statistics.h"
#include "support/passat.h"
#include "support/sine_road.h"

namespace ridefit::simulate {
namespace {

using model::HalfCarOutputs;

io::HalfCarFile ajayi(const io::ModelOverrides& overrides = {}) {
  return io::load_half_car(testing::dataset("vehicles/ajayi_half_car.yaml"), overrides);
}

// The first sample where |x| exceeds `threshold`.
double onset_s(const HalfCarResponse& r, double HalfCarOutputs::*member, double threshold) {
  for (std::size_t k = 0; k < r.samples.size(); ++k) {
    if (std::abs(r.samples[k].*member) > threshold) return r.time_s[k];
  }
  return -1.0;
}

TEST(HalfCarSimulation, RearWheelMeetsTheCleatAWheelbaseLater) {
  road::CleatParameters cleat;
  cleat.speed_m_per_s = 10.0;
  cleat.start_distance_m = 1.0;
  const auto road = road::make_cleat_road(cleat);
  const model::HalfCar car = ajayi().make_model();
  HalfCarSimulationOptions options;
  options.output_rate_Hz = 2000.0;
  const HalfCarResponse r = simulate(car, road, options);
  EXPECT_DOUBLE_EQ(r.rear_delay_s, 2.8 / 10.0);
  const double front = onset_s(r, &HalfCarOutputs::front_road_m, 1e-6);
  const double rear = onset_s(r, &HalfCarOutputs::rear_road_m, 1e-6);
  EXPECT_NEAR(rear - front, 0.28, 1.0 / 2000.0);
  // The tyre-force peaks of the impacts lie a wheelbase apart too (the body carries a little of
  // the front impact to the rear wheel earlier, so compare peaks, not onsets).
  auto peak_time = [&](double HalfCarOutputs::*member) {
    std::size_t best = 0;
    for (std::size_t k = 0; k < r.samples.size(); ++k) {
      if (std::abs(r.samples[k].*member) > std::abs(r.samples[best].*member)) best = k;
    }
    return r.time_s[best];
  };
  EXPECT_NEAR(peak_time(&HalfCarOutputs::rear_tyre_force_N) -
                  peak_time(&HalfCarOutputs::front_tyre_force_N),
              0.28, 0.005);
}

TEST(HalfCarSimulation, SymmetricCarOnARigShakingBothAxlesDoesNotPitch) {
  // a1 = a2, equal axles, seat over the centre of gravity, both wheels on the same input.
  const model::HalfCar car = ajayi({{"seat_distance_m", "0"}}).make_model();
  const testing::SineRoad road(0.01, 1.5, 5.0);
  HalfCarSimulationOptions options;
  options.rear_delay_s = 0.0;
  const HalfCarResponse r = simulate(car, road, options);
  const double heave = signal::rms(r.channel(&HalfCarOutputs::body_acc_m_per_s2));
  const double pitch = signal::rms(r.channel(&HalfCarOutputs::pitch_acc_rad_per_s2));
  EXPECT_GT(heave, 0.1);
  EXPECT_LT(pitch, 1e-9 * heave);
  // With the seat ahead of the centre of gravity the same input does pitch the body.
  const HalfCarResponse offset = simulate(ajayi().make_model(), road, options);
  EXPECT_GT(signal::rms(offset.channel(&HalfCarOutputs::pitch_acc_rad_per_s2)), 1e-4 * heave);
}

TEST(HalfCarSimulation, TimeRoadsNeedAnExplicitRearDelay) {
  const testing::SineRoad road(0.01, 1.5, 1.0);
  EXPECT_THROW(simulate(ajayi().make_model(), road, {}), InputError);
}

road::SpatialProfileRoad iso_road(road::Iso8608Class road_class, double speed_m_per_s,
                                  double duration_s) {
  road::Iso8608RoadParameters p;
  p.road_class = road_class;
  p.random.speed_m_per_s = speed_m_per_s;
  p.random.duration_s = duration_s;
  p.random.seed = 7;
  return road::make_iso8608_road(p);
}

double body_rms(const model::HalfCar& car, const road::RoadInput& road) {
  HalfCarSimulationOptions options;
  options.output_rate_Hz = 500.0;
  return signal::rms(simulate(car, road, options).channel(&HalfCarOutputs::body_acc_m_per_s2));
}

// Seed 001's point: a skyhook damper within limits isolates the body better than the passive
// damper. Class C road at 50 km/h for 20 s; skyhook c_sky = 3000 Ns/m within 300–3000 Ns/m
// against the passive 1000 Ns/m. Measured: 0.761 → 0.536 m/s^2 (−30 %); asserted: at least −20 %.
TEST(HalfCarSimulation, SkyhookLowersBodyAccelerationOnARoughRoad) {
  const auto road = iso_road(road::Iso8608Class::kC, 50.0 / 3.6, 20.0);
  const double passive = body_rms(ajayi().make_model(), road);
  const double skyhook = body_rms(ajayi({{"control.law", "skyhook"}}).make_model(), road);
  EXPECT_LT(skyhook, 0.8 * passive);
  EXPECT_GT(skyhook, 0.5 * passive);  // a damper that can only dissipate has its limits
}

// Seed 000's point carried to the half car: strut friction on the front axle stiffens the ride
// on a smooth road. ISO class A at 50 km/h for 20 s, front strut in stick/slip at Fc = 60 N
// against Fc = 0. Measured: 0.192 → 0.217 m/s^2 (+12.7 %); asserted: +5 % to +30 %.
TEST(HalfCarSimulation, FrontStrutFrictionRaisesBodyAccelerationOnASmoothRoad) {
  const auto road = iso_road(road::Iso8608Class::kA, 50.0 / 3.6, 20.0);
  const double free = body_rms(
      ajayi({{"front.suspension", "strut"}, {"front.coulomb_force_N", "0"}}).make_model(), road);
  const double friction = body_rms(ajayi({{"front.suspension", "strut"}}).make_model(), road);
  EXPECT_GT(friction, 1.05 * free);
  EXPECT_LT(friction, 1.3 * free);
}

}  // namespace
}  // namespace ridefit::simulate
