// A rig record's inputs kink at its samples when they are C1 cubics (uneven time stamps, a
// measured velocity) or straight lines (a command): the strut's steps end on those samples
// (IntegratorOptions::steps_end_on_outputs), and a uniform record's C2 spline is left alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "ridefit/simulate/esdirk_integrator.h"
#include "ridefit/simulate/strut_test_response.h"
#include "ridefit/simulate/strut_test_system.h"

namespace ridefit::simulate {
namespace {

constexpr double kPi = std::numbers::pi;

model::StrutTestParameters<double> mr_strut() {
  model::StrutTestParameters<double> p{};
  p.dahl_sigma0_N_per_m = 2.0e6;
  p.coulomb_force_N = 150.0;
  p.dahl_exponent = 1.0;
  p.top_mount_stiffness_N_per_m = 1e9;  // a press: the quasi-static path
  p.damping_Ns_per_m = 1500.0;
  p.damping_per_command_Ns_per_m = 2500.0;
  p.coulomb_force_per_command_N = 1100.0;
  return p;
}

// Broadband to 41 Hz with a measured velocity at 1 kHz, as the NEES random test: the velocity
// sensor's noise (1 mm/s RMS, seeded) is what makes the Hermite through it kink at the samples.
struct Record {
  std::vector<double> t, x, v, u;
};
Record broadband(bool with_velocity) {
  Record r;
  std::mt19937 random(33);
  std::normal_distribution<double> noise(0.0, 1e-3);
  for (int k = 0; k < 2000; ++k) {
    const double t = k * 1e-3;
    r.t.push_back(t);
    double x = 0.0, v = 0.0;
    for (const auto& [a, f] :
         {std::pair{0.003, 1.3}, {0.0015, 4.7}, {0.0006, 11.0}, {0.0003, 23.0}, {0.0002, 41.0}}) {
      x += a * std::sin(2 * kPi * f * t + f);
      v += a * 2 * kPi * f * std::cos(2 * kPi * f * t + f);
    }
    r.x.push_back(x);
    if (with_velocity) r.v.push_back(v + noise(random));
    r.u.push_back(1.0 + std::tanh(20.0 * std::sin(2 * kPi * t / 1.4)));
  }
  return r;
}

bool every_sample_ends_a_step(const EsdirkStepHistory& h, const std::vector<double>& t) {
  std::vector<double> ends;
  for (std::size_t i = 0; i < h.step_count(); ++i) ends.push_back(h.start_s[i] + h.length_s[i]);
  for (std::size_t k = 1; k < t.size(); ++k) {
    const bool found = std::any_of(ends.begin(), ends.end(), [&](double e) {
      return std::abs(e - t[k]) <= 1e-12 * std::max(1.0, t[k]);
    });
    if (!found) return false;
  }
  return true;
}

TEST(RigInputKinks, StepsEndOnTheSamplesOfAMeasuredVelocityAndASwitchingCommand) {
  const Record r = broadband(true);
  const auto p = mr_strut();
  const RigDisplacement x(r.t, r.x, RigInterpolation::kSpline, r.v);
  EXPECT_TRUE(x.kinks_at_samples());
  const auto history = strut_test_steps(r.t, r.x, p, {}, r.u, r.v);
  EXPECT_TRUE(every_sample_ends_a_step(history, r.t));
  // The same run stepping across the samples: a step across a kink loses the method's order.
  const RigDisplacement u(r.t, r.u, RigInterpolation::kLinear);
  const StrutTestSystem system(p, x, &u);
  IntegratorOptions across = esdirk_options(StrutTestSolverOptions{});
  const auto y0 = strut_test_start(p, r.x[0], r.u[0]);
  const Trajectory free_steps = integrate_esdirk(system, y0, r.t, across);
  across.steps_end_on_outputs = true;
  const Trajectory landed = integrate_esdirk(system, y0, r.t, across);
  // Measured here: 2 161 error-test failures stepping across, 135 landing; on the NEES record's
  // first half 19 139 against 2 994 (and 268 474 against 256 926 steps).
  EXPECT_LT(3 * landed.statistics.error_test_failures, free_steps.statistics.error_test_failures)
      << landed.statistics.error_test_failures << " against "
      << free_steps.statistics.error_test_failures;
  EXPECT_LT(landed.statistics.steps + landed.statistics.error_test_failures,
            free_steps.statistics.steps + free_steps.statistics.error_test_failures);
  // Both at the same tolerance, so they agree to it.
  double worst = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    worst = std::max(worst, std::abs(landed.state_at(k)[1] - free_steps.state_at(k)[1]));
    scale = std::max(scale, std::abs(free_steps.state_at(k)[1]));
  }
  EXPECT_LT(worst, 1e-3 * scale);
}

TEST(RigInputKinks, AUniformRecordsSplineIsSteppedAcross) {
  const Record r = broadband(false);
  const RigDisplacement x(r.t, r.x);
  EXPECT_FALSE(x.kinks_at_samples());
  auto p = mr_strut();
  p.damping_per_command_Ns_per_m = 0.0;
  p.coulomb_force_per_command_N = 0.0;
  EXPECT_FALSE(rig_integrator_options({}, x, p, r.u).steps_end_on_outputs);  // command unused
  EXPECT_TRUE(rig_integrator_options({}, x, mr_strut(), r.u).steps_end_on_outputs);
  const std::vector<double> constant(r.t.size(), 0.5);
  EXPECT_FALSE(rig_integrator_options({}, x, mr_strut(), constant).steps_end_on_outputs);
  std::vector<double> uneven = r.t;
  for (std::size_t k = 1; k < uneven.size(); k += 2) uneven[k] += 1e-4;  // rounded stamps
  EXPECT_TRUE(RigDisplacement(uneven, r.x).kinks_at_samples());
  EXPECT_TRUE(RigDisplacement(r.t, r.x, RigInterpolation::kLinear).kinks_at_samples());
}

}  // namespace
}  // namespace ridefit::simulate
