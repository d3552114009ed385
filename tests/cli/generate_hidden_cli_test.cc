// `ridefit generate-hidden`: records and truth files, determinism, another road for record 2,
// the effect actually present in the truth, and bad specs (exit 2, nothing written).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <string>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/fitting/psd_fit.h"
#include "ridefit/io/quarter_car_file.h"
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

// `baseline:` writes NAME_baseline.yaml: the model with values off as a data sheet's are, each
// within its stated width (synthetic/datasheet_values.h) of the model's, the same for the same
// seed, and the records as without it (the baseline changes no record).
TEST(GenerateHiddenCli, WritesADatasheetBaselineWithinItsTolerances) {
  testing::TempDir dir("ridefit_hidden_cli");
  const std::string model = dataset("hidden/baselines/passat_slip.yaml");
  const auto plain = dir.write("plain.yaml", spec());
  const auto sheet =
      dir.write("sheet.yaml", spec("    baseline: {model: " + model + ", datasheet_seed: 9}\n"));
  const std::filesystem::path a = dir.path() / "a", b = dir.path() / "b";
  ASSERT_EQ(run_cli("generate-hidden " + plain + " -o " + a.string()).exit_code, 0);
  ASSERT_EQ(run_cli("generate-hidden " + sheet + " -o " + b.string()).exit_code, 0);
  EXPECT_FALSE(std::filesystem::exists(a / "lift_baseline.yaml"));
  EXPECT_EQ(testing::text_of(a / "lift.csv"), testing::text_of(b / "lift.csv"));
  const auto base = io::load_quarter_car(model).parameters;
  const auto drawn = io::load_quarter_car(b / "lift_baseline.yaml").parameters;
  const std::pair<double, double> pairs[] = {
      {drawn.sprung_mass_kg / base.sprung_mass_kg, 0.03},
      {drawn.unsprung_mass_kg / base.unsprung_mass_kg, 0.03},
      {drawn.tyre_stiffness_N_per_m / base.tyre_stiffness_N_per_m, 0.08},
      {drawn.spring_stiffness_N_per_m / base.spring_stiffness_N_per_m, 0.08},
      {drawn.damping_Ns_per_m / base.damping_Ns_per_m, 0.12},
      {drawn.top_mount_stiffness_N_per_m / base.top_mount_stiffness_N_per_m, 0.15}};
  int moved = 0;
  for (const auto& [ratio, width] : pairs) {
    EXPECT_LE(std::abs(ratio - 1.0), width) << ratio;
    moved += std::abs(ratio - 1.0) > 1e-6 ? 1 : 0;
  }
  EXPECT_EQ(moved, 6);
  const double sigma0 = drawn.dahl_sigma0_N_per_m / base.dahl_sigma0_N_per_m;
  EXPECT_GE(sigma0, 0.5);
  EXPECT_LE(sigma0, 2.0);
  EXPECT_NE(testing::text_of(b / "lift_baseline.yaml").find("datasheet_seed 9"), std::string::npos);
}

std::string rig_spec(
    const std::string& rig = "{amplitudes_mm: [3, 1.5], frequencies_Hz: [0.7, 2.3]}",
    const std::string& set = "{gas_stiffness_N_per_m: 15000}") {
  return "datasets:\n  - name: gas\n    kind: strut_rig\n    model: " +
         dataset("vehicles/passat_b8_front.yaml") + "\n    set: " + set +
         "\n    effects: [gas_force]\n    rig: " + rig +
         "\n    duration_s: 4\n    sample_rate_Hz: 500\n    seed: 9\n";
}

TEST(GenerateHiddenCli, WritesStrutRigRecordsWithTheTruthsForce) {
  testing::TempDir dir("ridefit_hidden_cli");
  const auto file = dir.write("spec.yaml", rig_spec());
  const auto a = (dir.path() / "a").string(), b = (dir.path() / "b").string();
  ASSERT_EQ(run_cli("generate-hidden " + file + " -o " + a).exit_code, 0);
  ASSERT_EQ(run_cli("generate-hidden " + file + " -o " + b).exit_code, 0);
  for (const char* name : {"gas.csv", "gas_2.csv", "gas_truth.yaml"}) {
    EXPECT_EQ(testing::text_of((std::filesystem::path(a) / name).string()),
              testing::text_of((std::filesystem::path(b) / name).string()))
        << name << " differs between two runs";
  }
  const auto r1 = fitting::load_hysteresis_record(std::filesystem::path(a) / "gas.csv");
  const auto r2 = fitting::load_hysteresis_record(std::filesystem::path(a) / "gas_2.csv");
  ASSERT_EQ(r1.time_s.size(), 2001u);
  EXPECT_EQ(r1.displacement_m.front(), 0.0);  // record 1 starts in sine phase
  EXPECT_NE(r2.displacement_m.front(), 0.0);  // record 2 has random phases
  // The gas rate is in the force: without it (same seed, same noise) the force differs by
  // exactly k_g·x, the gas spring being in parallel with the rest of the strut.
  const auto no_gas = dir.write("no_gas.yaml", rig_spec("{amplitudes_mm: [3, 1.5], frequencies_Hz: "
                                                        "[0.7, 2.3]}",
                                                        "{gas_stiffness_N_per_m: 0}"));
  const auto c = (dir.path() / "c").string();
  ASSERT_EQ(run_cli("generate-hidden " + no_gas + " -o " + c).exit_code, 0);
  const auto r0 = fitting::load_hysteresis_record(std::filesystem::path(c) / "gas.csv");
  double worst = 0.0;
  for (std::size_t k = 0; k < r1.force_N.size(); ++k) {
    worst =
        std::max(worst, std::abs(r1.force_N[k] - r0.force_N[k] - 15000.0 * r1.displacement_m[k]));
  }
  EXPECT_LT(worst, 1e-2);  // the CSV's 6 significant digits
  const std::string truth =
      testing::text_of((std::filesystem::path(a) / "gas_truth.yaml").string());
  EXPECT_NE(truth.find("gas_stiffness_N_per_m: 15000"), std::string::npos) << truth;
}

// A rig dataset's data-sheet baseline: the model whose strut the rig diagnosis puts on the rig,
// its strut's values off within the sheet's tolerances.
TEST(GenerateHiddenCli, WritesARigDatasheetBaseline) {
  testing::TempDir dir("ridefit_hidden_cli");
  const std::string model = dataset("hidden/baselines/passat_slip.yaml");
  const auto file = dir.write(
      "spec.yaml", rig_spec() + "    baseline: {model: " + model + ", datasheet_seed: 4}\n");
  const auto a = dir.path() / "a";
  ASSERT_EQ(run_cli("generate-hidden " + file + " -o " + a.string()).exit_code, 0);
  ASSERT_TRUE(std::filesystem::exists(a / "gas_baseline.yaml"));
  const auto sheet = io::load_quarter_car(a / "gas_baseline.yaml").parameters;
  const auto own = io::load_quarter_car(model).parameters;
  const double damping = sheet.damping_Ns_per_m / own.damping_Ns_per_m - 1.0;
  EXPECT_NE(damping, 0.0);
  EXPECT_LE(std::abs(damping), 0.12);
  const double mount = sheet.top_mount_stiffness_N_per_m / own.top_mount_stiffness_N_per_m - 1.0;
  EXPECT_NE(mount, 0.0);
  EXPECT_LE(std::abs(mount), 0.15);
}

struct BadSpec {
  std::string name;
  std::string text;
  std::string expected;
};

class GenerateHiddenBadSpec : public ::testing::TestWithParam<BadSpec> {};

// Names the case in ctest's listing (gtest would print the object's bytes, which change
// from build to build).
void PrintTo(const BadSpec& c, std::ostream* os) { *os << c.name; }

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
                "high_pass_Hz < low_pass_Hz"},
        BadSpec{"RigAmplitudesWithoutFrequencies",
                rig_spec("{amplitudes_mm: [3, 1.5], frequencies_Hz: [0.7]}"),
                "as many amplitudes_mm as frequencies_Hz"},
        BadSpec{"RigZeroFrequency", rig_spec("{amplitudes_mm: [3], frequencies_Hz: [0]}"),
                "frequencies must be finite and > 0 Hz"},
        BadSpec{"RigUnknownStrutKey",
                rig_spec("{amplitudes_mm: [3], frequencies_Hz: [1]}", "{gas_rate: 1}"),
                "'gas_rate' is not a strut-test parameter"},
        BadSpec{"BaselineWithSeedAndErrors",
                spec("    baseline: {model: " + dataset("hidden/baselines/passat_slip.yaml") +
                     ", datasheet_seed: 3, errors: {sprung_mass_kg: 0.02}}\n"),
                "give either datasheet_seed"},
        BadSpec{"BaselineErrorBelowMinusOne",
                spec("    baseline: {model: " + dataset("hidden/baselines/passat_slip.yaml") +
                     ", errors: {sprung_mass_kg: -1.5}}\n"),
                "expected a share in (-1, 10]"},
        BadSpec{"BaselineErrorOnAnUnknownKey",
                spec("    baseline: {model: " + dataset("hidden/baselines/passat_slip.yaml") +
                     ", errors: {sprung_mass: 0.02}}\n"),
                "'sprung_mass' is not a quarter-car parameter"},
        BadSpec{"RigBaselineWithoutAModel", rig_spec() + "    baseline: {datasheet_seed: 3}\n",
                "model"},
        BadSpec{"RigWithASensor", rig_spec() + "    sensor: {noise: 0.01}\n",
                "takes noise_N, not a sensor"}),
    [](const ::testing::TestParamInfo<BadSpec>& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace ridefit
