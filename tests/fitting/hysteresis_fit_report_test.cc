// The report of a hysteresis fit: the seed's calibration value per record, the friction line
// from the per-file values, and the summary's text and JSON.
#include "ridefit/fitting/hysteresis_fit_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "support/throws_input_error.h"

namespace ridefit::fitting {
namespace {

using testing::throws_input_error;

// Five sine cycles with a pure friction force of ±50 N: the loop is 100 N high at x = 0.
HysteresisRecord friction_loop(const std::string& source) {
  HysteresisRecord r;
  r.source = source;
  for (int k = 0; k <= 500; ++k) {
    const double t = k / 100.0;
    r.time_s.push_back(t);
    const double phase = 2.0 * std::numbers::pi * t + 0.1;  // no sample on a zero crossing
    r.displacement_m.push_back(0.003 * std::sin(phase));
    r.force_N.push_back(std::cos(phase) > 0.0 ? 50.0 : -50.0);
  }
  return r;
}

// A fit with a shared σ0 and the Coulomb force per file, 40, 50, 60 N.
HysteresisFitResult per_file_fit() {
  HysteresisFitResult fit;
  fit.parameters = {{"dahl_sigma0_N_per_m", "", 5e6, 1e4},
                    {"coulomb_force_N", "a.csv", 40.0, 0.5},
                    {"coulomb_force_N", "b.csv", 50.0, 0.5},
                    {"coulomb_force_N", "c.csv", 60.0, 0.5}};
  fit.iterations = 3;
  fit.termination = "converged";
  return fit;
}

TEST(FrictionCompression, TheLineThroughAFitsPerFileFrictionValues) {
  const double compression_m[3] = {0.0, 0.002, 0.004};
  const auto line = fit_friction_compression(per_file_fit(), compression_m);
  EXPECT_NEAR(line.intercept_N, 40.0, 1e-9);
  EXPECT_NEAR(line.slope_N_per_m, 5000.0, 1e-6);
  ASSERT_TRUE(line.slope_se_N_per_m.has_value());
  // Without per-file friction values there is no line.
  HysteresisFitResult shared;
  shared.parameters = {{"coulomb_force_N", "", 45.0, 0.5}};
  EXPECT_TRUE(throws_input_error([&] { fit_friction_compression(shared, compression_m); },
                                 "compressions for 0 friction values"));
}

TEST(HysteresisFitReport, CalibrationPerRecordLineAndSummary) {
  const double compression_m[3] = {0.0, 0.002, 0.004};
  HysteresisRecord short_record = friction_loop("short.csv");
  short_record.time_s.resize(60);  // under one cycle: no calibration value
  short_record.displacement_m.resize(60);
  short_record.force_N.resize(60);
  const auto fit = per_file_fit();
  const auto report =
      report_hysteresis_fit({friction_loop("a.csv"), friction_loop("b.csv"), short_record}, fit,
                            "the model file", compression_m);
  ASSERT_EQ(report.calibration.size(), 3u);
  ASSERT_TRUE(report.calibration[0].has_value());
  EXPECT_NEAR(report.calibration[0]->mean_N, 50.0, 1e-9);
  EXPECT_FALSE(report.calibration[2].has_value());
  ASSERT_TRUE(report.friction_line.has_value());

  std::ostringstream text;
  write_summary(text, fit, report);
  EXPECT_NE(text.str().find("fit of 3 file(s) from the model file: 3 iterations"),
            std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("Fc = 40 N + 5 N/mm · compression"), std::string::npos) << text.str();

  const auto j = summary_json(fit, report);
  EXPECT_EQ(j["start"], "the model file");
  EXPECT_EQ(j["calibration_friction_N"][2]["mean"], nullptr);
  EXPECT_NEAR(j["friction_against_compression"]["slope_N_per_m"].get<double>(), 5000.0, 1e-6);
  EXPECT_EQ(j["parameters"].size(), 4u);
}

}  // namespace
}  // namespace ridefit::fitting
