// The Stribeck pair of the strut rig model can be fitted like the other strut parameters
// (kStrutParameters): recovery from a synthetic dynamic rig test.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/synthetic/multisine.h"
#include "support/cvode_rig_record.h"

namespace ridefit::fitting {
namespace {

// The Passat strut breaking away at 90 N, sliding at 60 N above 5 mm/s.
model::StrutTestParameters<double> truth() {
  auto p = model::dahl_strut_on_rig(5e6, 60.0, 1.0, 488000.0, 887.0);
  p.static_friction_force_N = 90.0;
  p.stribeck_velocity_m_per_s = 0.005;
  return p;
}

// Three sines (0.7, 2.3 and 6.1 Hz) for 10 s at 1 kHz: damper speeds from 0 to ~60 mm/s.
HysteresisRecord dynamic(const model::StrutTestParameters<double>& p) {
  // CVODE at rtol 1e-10 on the analytic multisine: not the solver the fit uses.
  return testing::cvode_rig_record(p, synthetic::lab_three_sines(), 10.0, 1000.0, "dynamic");
}

TEST(StribeckFit, TheNewParametersAreFittableByName) {
  EXPECT_EQ(kStrutParameters.size(), 27u);
  const std::size_t fs = strut_parameter_index("static_friction_force_N");
  const std::size_t vs = strut_parameter_index("stribeck_velocity_m_per_s");
  auto p = truth();
  EXPECT_EQ(strut_parameter(p, fs), 90.0);
  EXPECT_EQ(strut_parameter(p, vs), 0.005);
  EXPECT_EQ(strut_parameter(p, strut_parameter_index("force_offset_N")), 0.0);
  EXPECT_TRUE(kStrutParameters[fs].in_model_file);
  EXPECT_TRUE(kStrutParameters[vs].in_model_file);
  EXPECT_GT(kStrutParameters[vs].lower, 0.0);  // 0 would switch the curve off
  // The default (off) is outside the bound: fitting it needs a start value.
  auto off = truth();
  off.stribeck_velocity_m_per_s = 0.0;
  HysteresisFitOptions options;
  options.free = {"stribeck_velocity_m_per_s"};
  EXPECT_THROW(fit_hysteresis({dynamic(truth())}, off, options), InputError);
}

TEST(StribeckFit, DynamicHistoryRecoversTheStribeckCurve) {
  const auto data = dynamic(truth());
  auto start = truth();
  start.coulomb_force_N = 40.0;  // every start at least 30 % off the truth
  start.static_friction_force_N = 60.0;
  start.stribeck_velocity_m_per_s = 0.01;
  HysteresisFitOptions options;
  options.free = {"coulomb_force_N", "static_friction_force_N", "stribeck_velocity_m_per_s"};
  const auto fit = fit_hysteresis({data}, start, options);
  ASSERT_TRUE(fit.converged) << fit.termination;
  EXPECT_NEAR(fit.parameters[0].value, 60.0, 0.01 * 60.0);
  EXPECT_NEAR(fit.parameters[1].value, 90.0, 0.01 * 90.0);
  EXPECT_NEAR(fit.parameters[2].value, 0.005, 0.01 * 0.005);
  EXPECT_LT(fit.residual_rms_N, 1e-2);
}

}  // namespace
}  // namespace ridefit::fitting
