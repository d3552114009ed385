// The PSD fit recovers the top-mount stiffness of the stick/slip quarter car from its spectra
// (seed 000 Section 4.2.2: 488 and 707 N/mm), the "measurement" simulated with CVODE.
#include "ridefit/fitting/psd_fit.h"

#include <gtest/gtest.h>

#include <memory>

#include "ridefit/io/input_error.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/road/measured_road.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "support/passat.h"

namespace ridefit::fitting {
namespace {

PsdMeasurement measure(double top_mount_N_per_m) {
  auto p = testing::passat_corner().parameters;
  p.top_mount_stiffness_N_per_m = top_mount_N_per_m;
  const model::QuarterCar car(model::DamperState::kStickSlip, p);
  road::Iso8608RoadParameters r;
  r.road_class = road::Iso8608Class::kA;
  r.random.speed_m_per_s = 50.0 / 3.6;
  r.random.duration_s = 30.0;
  r.random.seed = 5;
  const auto road = road::make_iso8608_road(r);
  simulate::SimulationOptions options;
  options.output_rate_Hz = 1000.0;
  const auto run = simulate::simulate(car, road, options);
  PsdMeasurement m;
  m.source = "simulated";
  m.time_s = run.time_s;
  m.sample_rate_Hz = 1000.0;
  m.road = std::make_shared<road::MeasuredRoad>(run.time_s, run.road_m);
  m.body_acc_m_per_s2 = run.body_acc_m_per_s2;
  m.wheel_acc_m_per_s2 = run.wheel_acc_m_per_s2;
  return m;
}

void expect_recovered(double truth, double start) {
  const auto m = measure(truth);
  auto p = testing::passat_corner().parameters;
  p.top_mount_stiffness_N_per_m = start;
  const model::QuarterCar car(model::DamperState::kStickSlip, p);
  PsdFitOptions options;
  options.free = {"top_mount_stiffness_N_per_m"};
  options.band_low_Hz = 8.0;
  options.band_high_Hz = 30.0;
  options.segment_s = 5.0;
  const auto fit = fit_psd(m, car, options);
  EXPECT_TRUE(fit.converged) << fit.termination;
  EXPECT_NEAR(fit.values[0], truth, 0.03 * truth) << "start " << start;
}

TEST(PsdFit, RecoversA488NPerMmTopMount) { expect_recovered(488000.0, 600000.0); }
TEST(PsdFit, RecoversA707NPerMmTopMount) { expect_recovered(707000.0, 560000.0); }

}  // namespace
}  // namespace ridefit::fitting
