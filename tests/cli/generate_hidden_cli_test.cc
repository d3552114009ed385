// `ridefit generate-hidden`: records and truth files, determinism, another road for record 2,
// the effect actually present in the truth, and bad specs (exit 2, nothing written).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "ridefit/fitting/psd_fit.h"
#include "support/cli_runner.h"
#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

using testing::dataset;
using testing::run_cli;

std::string spec(const std::string& extra = "", const std::string& set = "{tyre_lift_off: 1}") {
  return "datasets:\n  - name: lift\n    model: " + dataset("hidden/baselines/passat_slip.yaml") +
         "\n    set: " + set + "\n    effects: [tyre_lift_off]\n    excitation: " +
         dataset("hidden/roads/iso8608_class_d_50kmh_30s.yaml") +
         "\n    duration_s: 8\n    sample_rate_Hz: 200\n    seed: 4\n" + extra;
}

TEST(GenerateHiddenCli, WritesRecordsAndTruthDeterministically) {
  testing::TempDir dir("ridefit_hidden_cli");
  const auto file = dir.write("spec.yaml", spec());
  const auto a = (dir.path() / "a").string(), b = (dir.path() / "b").string();
  ASSERT_EQ(run_cli("generate-hidden " + file + " -o " + a).exit_code, 0);
  ASSERT_EQ(run_cli("generate-hidden " + file + " -o " + b).exit_code, 0);
  for (const char* name : {"lift.csv", "lift_2.csv", "lift_truth.yaml"}) {
    ASSERT_TRUE(std::filesystem::exists(std::filesystem::path(a) / name)) << name;
    EXPECT_EQ(testing::text_of((std::filesystem::path(a) / name).string()),
              testing::text_of((std::filesystem::path(b) / name).string()))
        << name << " differs between two runs";
  }
  const auto r1 = fitting::load_psd_measurement(std::filesystem::path(a) / "lift.csv");
  const auto r2 = fitting::load_psd_measurement(std::filesystem::path(a) / "lift_2.csv");
  ASSERT_EQ(r1.time_s.size(), r2.time_s.size());
  EXPECT_NEAR(r1.time_s.back(), 8.0, 1e-9);
  // Record 2 drives another realisation of the road.
  EXPECT_NE(r1.road->at(4.0).elevation_m, r2.road->at(4.0).elevation_m);
  const std::string truth =
      testing::text_of((std::filesystem::path(a) / "lift_truth.yaml").string());
  EXPECT_NE(truth.find("tyre_lift_off"), std::string::npos);
  EXPECT_NE(truth.find("not to be read by the diagnosis"), std::string::npos);
  // Another noise seed changes the records.
  const auto c = (dir.path() / "c").string();
  ASSERT_EQ(run_cli("generate-hidden " + file + " -o " + c + " --seed 5").exit_code, 0);
  EXPECT_NE(testing::text_of((std::filesystem::path(a) / "lift.csv").string()),
            testing::text_of((std::filesystem::path(c) / "lift.csv").string()));
}

struct BadSpec {
  std::string name;
  std::string text;
  std::string expected;
};

class GenerateHiddenBadSpec : public ::testing::TestWithParam<BadSpec> {};

TEST_P(GenerateHiddenBadSpec, ExitTwoNamingTheKeyAndNothingWritten) {
  testing::TempDir dir("ridefit_hidden_bad");
  const auto file = dir.write("spec.yaml", GetParam().text);
  const auto out = (dir.path() / "out").string();
  const auto run = run_cli("generate-hidden " + file + " -o " + out);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(GetParam().expected), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, GenerateHiddenBadSpec,
    ::testing::Values(
        BadSpec{
            "UnknownEffect",
            spec("", "{}").replace(spec("", "{}").find("[tyre_lift_off]"), 15, "[tyre_liftoff]"),
            "unknown effect 'tyre_liftoff'"},
        BadSpec{"UnknownModelKey", spec("", "{tyre_dampin: 3}"), "tyre_dampin"},
        BadSpec{"UnknownDatasetKey", spec("    colour: red\n"), "colour"},
        BadSpec{"NoRecords", spec("    records: 0\n"), "records"},
        BadSpec{"NegativeNoise", spec("    sensor: {noise: -0.1}\n"), "noise"},
        BadSpec{"BandAboveNyquist", spec("    sensor: {low_pass_Hz: 150}\n"), "Nyquist"},
        BadSpec{"InvertedBand", spec("    sensor: {high_pass_Hz: 90, low_pass_Hz: 50}\n"),
                "high_pass_Hz < low_pass_Hz"}),
    [](const ::testing::TestParamInfo<BadSpec>& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace ridefit
