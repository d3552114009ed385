// The strut rig model and its five-parameter fit against records that CVODE made at rtol 1e-10
// from an analytic random displacement: what ridefit's ESDIRK strut solver computes, and what
// the fit recovers, on data that neither made.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "ridefit/fitting/hysteresis_fit.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/simulate/strut_test_response.h"
#include "ridefit/synthetic/load_cell.h"
#include "support/controlled_damper_record.h"
#include "support/cvode_rig_record.h"
#include "support/passat.h"

namespace ridefit::fitting {
namespace {

model::StrutTestParameters<double> set_a() {
  return model::dahl_strut_on_rig(2e6, 90.0, 1.5, 600e3, 1500.0);
}
model::StrutTestParameters<double> set_b() {
  return model::dahl_strut_on_rig(8e5, 30.0, 0.8, 400e3, 2600.0);
}

HysteresisRecord cvode_record(const model::StrutTestParameters<double>& p, double duration_s,
                              double noise_share = 0.0, unsigned seed = 3) {
  // A random displacement: 40 sines log-spaced over 0.5–20 Hz (about 4 mm RMS), seeded phases.
  auto r =
      testing::cvode_rig_record(p, testing::random_rig_motion(seed), duration_s, 1000.0, "cvode");
  std::mt19937_64 rng(seed + 100);
  r.force_N =
      synthetic::read_load_cell(r.force_N, {noise_share * signal::rms(r.force_N), 0.0}, rng);
  return r;
}

TEST(StrutOnCvodeRecord, ForceAtTheTrueParametersWithinFiveHundredthsOfAPercent) {
  for (const auto& p : {set_a(), set_b()}) {
    const auto r = cvode_record(p, 20.0);
    const auto force = simulate::strut_test_force<double>(r.time_s, r.displacement_m, p, p);
    ASSERT_TRUE(force.has_value());
    std::vector<double> residual;
    for (std::size_t k = 0; k < force->size(); ++k) residual.push_back((*force)[k] - r.force_N[k]);
    EXPECT_LT(signal::rms(residual), 5e-4 * signal::rms(r.force_N))
        << "sigma0 " << p.dahl_sigma0_N_per_m << ": residual RMS " << signal::rms(residual);
  }
}

void expect_recovered(const HysteresisRecord& r, const model::StrutTestParameters<double>& truth,
                      double share) {
  // Every start off its truth: σ0 by a factor 2.5, the others by 35-40 %.
  const auto start = model::dahl_strut_on_rig(
      0.4 * truth.dahl_sigma0_N_per_m, 1.4 * truth.coulomb_force_N, 1.35 * truth.dahl_exponent,
      1.35 * truth.top_mount_stiffness_N_per_m, 0.65 * truth.damping_Ns_per_m);
  HysteresisFitOptions options;
  options.free = {"dahl_sigma0_N_per_m", "coulomb_force_N", "dahl_exponent",
                  "top_mount_stiffness_N_per_m", "damping_Ns_per_m"};
  const auto fit = fit_hysteresis({r}, start, options);
  ASSERT_TRUE(fit.converged) << fit.termination;
  const double expected[5] = {truth.dahl_sigma0_N_per_m, truth.coulomb_force_N, truth.dahl_exponent,
                              truth.top_mount_stiffness_N_per_m, truth.damping_Ns_per_m};
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(fit.parameters[i].value, expected[i], share * expected[i])
        << fit.parameters[i].name;
  }
}

TEST(StrutFitOnCvodeRecord, CleanRecordsGiveAllFiveWithinOnePercent) {
  expect_recovered(cvode_record(set_a(), 20.0), set_a(), 0.01);
  expect_recovered(cvode_record(set_b(), 20.0), set_b(), 0.01);
}

TEST(StrutFitOnCvodeRecord, OnePercentNoiseGivesAllFiveWithinThreePercent) {
  expect_recovered(cvode_record(set_a(), 20.0, 0.01), set_a(), 0.03);
  expect_recovered(cvode_record(set_b(), 20.0, 0.01), set_b(), 0.03);
}

}  // namespace
}  // namespace ridefit::fitting
