// The integration-resolution stop (integration_resolution.h) on a fit along a flat valley: a
// digressive damper's knee traded against the damping on either side of it. Started 50 % from
// the knee and a third from both damping coefficients, on a noisy record (the stop's second
// condition, a rejected step the scatter decided, is the one a noisy record meets), the fit must
// end where Ceres' own tolerances end it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/synthetic/reference_rig_record.h"
#include "support/fitted_value.h"

namespace ridefit {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(ResolutionStop, EndsAlongAFlatValleyWhereCeresWould) {
  model::StrutTestParameters<double> truth{};
  truth.coulomb_force_N = 0.0;  // the valley is the damper's own: no friction beside it
  truth.top_mount_stiffness_N_per_m = 3.0e6;
  truth.damping_Ns_per_m = 1500.0;
  truth.damper_knee_velocity_m_per_s = 0.12;
  truth.damping_above_knee_Ns_per_m = 500.0;
  // Two tones from rest: velocities to 0.4 m/s, well past the knee, and the slow ones below it.
  auto x = [](double t) {
    return 0.012 * (1.0 - std::cos(2 * kPi * 1.5 * t)) +
           0.004 * (1.0 - std::cos(2 * kPi * 11.0 * t));
  };
  fitting::HysteresisRecord record =
      synthetic::reference_rig_record(synthetic::sample_times(2001, 1000.0), x, truth, {}, "knee");
  std::mt19937 rng(20261128);
  std::normal_distribution<double> noise(0.0, 10.0);  // N: about 1 % of the force's spread
  for (double& f : record.force_N) f += noise(rng);

  model::StrutTestParameters<double> start = truth;
  start.damper_knee_velocity_m_per_s = 0.18;
  start.damping_Ns_per_m = 1000.0;
  start.damping_above_knee_Ns_per_m = 750.0;
  fitting::HysteresisFitOptions options;
  options.free = {"damping_Ns_per_m", "damper_knee_velocity_m_per_s",
                  "damping_above_knee_Ns_per_m"};
  const auto stopped = fitting::fit_hysteresis({record}, start, options);
  options.stop_at_integration_resolution = false;
  const auto full = fitting::fit_hysteresis({record}, start, options);

  ASSERT_TRUE(stopped.converged) << stopped.termination;
  ASSERT_TRUE(full.converged) << full.termination;
  for (const char* name :
       {"damping_Ns_per_m", "damper_knee_velocity_m_per_s", "damping_above_knee_Ns_per_m"}) {
    const double a = testing::fitted_value(stopped, name), b = testing::fitted_value(full, name);
    // Both end at the same point: within a fifth of the parameter's standard error.
    const double se = stopped.parameters.empty() ? 0.0 : [&] {
      for (const auto& p : stopped.parameters) {
        if (p.name == name && p.standard_error) return *p.standard_error;
      }
      return 0.0;
    }();
    ASSERT_GT(se, 0.0) << name;
    EXPECT_LT(std::abs(a - b), 0.2 * se) << name << ": " << a << " against " << b;
  }
  // And that point is the truth, within what 1 % noise leaves.
  EXPECT_NEAR(testing::fitted_value(stopped, "damper_knee_velocity_m_per_s"), 0.12, 0.03 * 0.12);
  EXPECT_NEAR(testing::fitted_value(stopped, "damping_Ns_per_m"), 1500.0, 0.03 * 1500.0);
  EXPECT_NEAR(testing::fitted_value(stopped, "damping_above_knee_Ns_per_m"), 500.0, 0.03 * 500.0);
  EXPECT_LE(stopped.iterations, full.iterations);
}

}  // namespace
}  // namespace ridefit
