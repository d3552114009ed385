// A rig test run on a strut (simulate/rig_test_run.h) against the reference force: CVODE at rtol
// 1e-10 on the test's exact displacement, another integrator than the one the run uses, and no
// sampling of the motion.
#include "ridefit/simulate/rig_test_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/simulate/strut_test_reference.h"
#include "support/passat.h"
#include "support/throws_input_error.h"

namespace ridefit::simulate {
namespace {

using testing::throws_input_error;

model::StrutTestParameters<double> strut_with_friction() {
  auto strut = fitting::strut_on_rig(testing::passat_corner().parameters);
  strut.coulomb_force_N = 60.0;
  strut.force_offset_N = 2.5;
  return strut;
}

double rms_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) sum += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(sum / static_cast<double>(a.size()));
}

double rms(const std::vector<double>& a) {
  return rms_difference(a, std::vector<double>(a.size(), 0.0));
}

class RigTestRun : public ::testing::TestWithParam<road::RigWaveform> {};

TEST_P(RigTestRun, RecordIsTheReferenceForceOnTheExactMotion) {
  road::RigTest test;
  test.waveform = GetParam();
  test.duration_s = 6.0;
  test.sample_rate_Hz = 500.0;
  test.amplitude_m = 0.008;
  test.frequency_Hz = 1.5;
  test.speed_m_per_s = 0.05;
  test.rms_m = 0.002;
  test.band_low_Hz = 0.5;
  test.band_high_Hz = 15.0;
  const auto strut = strut_with_friction();
  const RigTestRecord record = simulate_rig_test(strut, test);
  const road::RigMotion motion(test);
  const std::vector<double> reference = reference_strut_test_force(
      record.time_s, [&](double t) { return motion.displacement_m(t); }, strut);
  ASSERT_EQ(record.force_N.size(), reference.size());
  // Within 0.05 % of the force's RMS; the triangle's corners between samples are cut by the
  // straight lines the run drives with, which the Dahl take-up after each reversal shows.
  const double bar = GetParam() == road::RigWaveform::kTriangle ? 0.01 : 5e-4;
  EXPECT_LT(rms_difference(record.force_N, reference), bar * rms(reference))
      << rms_difference(record.force_N, reference) << " N of " << rms(reference) << " N";
  EXPECT_NEAR(record.displacement_m[7], motion.displacement_m(record.time_s[7]), 1e-15);
  EXPECT_NEAR(record.velocity_m_per_s[7], motion.velocity_m_per_s(record.time_s[7]), 1e-13);
  EXPECT_GT(record.peak_force_N, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Waveforms, RigTestRun,
                         ::testing::Values(road::RigWaveform::kSine, road::RigWaveform::kTriangle,
                                           road::RigWaveform::kRandom),
                         [](const auto& case_info) {
                           return std::string(road::waveform_name(case_info.param));
                         });

TEST(RigTestRunLimits, AForceBeyondTheRigsIsRefusedWithItsPeak) {
  road::RigTest test;
  test.amplitude_m = 0.02;
  test.frequency_Hz = 10.0;
  test.duration_s = 1.0;
  road::RigLimits rig;
  rig.force_N = 500.0;
  EXPECT_TRUE(throws_input_error([&] { simulate_rig_test(strut_with_friction(), test, rig); },
                                 "beyond the rig's 0.5 kN (rig.force_N)"));
  rig.force_N = 20e3;
  const RigTestRecord record = simulate_rig_test(strut_with_friction(), test, rig);
  EXPECT_GT(record.peak_force_N, 500.0);
  test.duration_s = 0.05;  // half a cycle: the test is checked before it runs
  EXPECT_TRUE(throws_input_error([&] { simulate_rig_test(strut_with_friction(), test); },
                                 "duration_s: 0.05 s is shorter than one cycle"));
}

}  // namespace
}  // namespace ridefit::simulate
