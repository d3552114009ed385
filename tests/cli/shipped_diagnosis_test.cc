// `ridefit diagnose` on every shipped hidden-effect dataset (datasets/hidden/, made by CVODE,
// diagnosed on ridefit's ESDIRK), each vehicle dataset from its data-sheet baseline
// (NAME_baseline.yaml: the truth's base with values off as a sheet's are, drawn by
// generate-hidden) with --tolerances datasheet: it names exactly what each truth hid, says "no
// missing effect" on the baseline's own records and "unexplained" for a sensor mount outside its
// library; on seed 000's case it fits the top mount's transition deflection within 10 % (issue 14),
// the body mass within 2 % and closes the gap below 0.5 dB.
#include <gtest/gtest.h>

#include <cmath>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "support/cli_runner.h"
#include "support/passat.h"
#include "support/temp_dir.h"

namespace ridefit {
namespace {

using testing::dataset;
using testing::run_cli;

struct ShippedCase {
  std::string name;                // datasets/hidden/NAME.csv, NAME_2.csv
  std::string baseline;            // relative to datasets/
  std::vector<std::string> named;  // what its truth file lists as hidden (sorted)
  bool unexplained = false;        // hidden outside the library
};

void PrintTo(const ShippedCase& c, std::ostream* os) { *os << c.name; }

class ShippedHiddenDataset : public ::testing::TestWithParam<ShippedCase> {};

TEST_P(ShippedHiddenDataset, NamesExactlyWhatItsTruthHid) {
  const ShippedCase& c = GetParam();
  testing::TempDir dir("ridefit_shipped_diagnosis");
  // A data-sheet baseline is diagnosed with the sheet's tolerances (its values refitted under
  // priors at the sheet's).
  const bool sheet = c.baseline.ends_with("_baseline.yaml");
  const auto run =
      run_cli("diagnose " + dataset(c.baseline) + " " + dataset("hidden/" + c.name + ".csv") + " " +
              dataset("hidden/" + c.name + "_2.csv") + (sheet ? " --tolerances datasheet" : "") +
              " --json -q --threads 1 -o " + (dir.path() / "diagnosis").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto start = run.output.find('{');
  ASSERT_NE(start, std::string::npos) << run.output;
  const auto j = nlohmann::json::parse(run.output.substr(start));
  std::vector<std::string> named = j["named"].get<std::vector<std::string>>();
  std::sort(named.begin(), named.end());
  EXPECT_EQ(named, c.named) << j["verdict"];
  const std::string verdict = j["verdict"];
  if (c.unexplained) {
    EXPECT_NE(verdict.find("significant disagreement remains"), std::string::npos) << verdict;
    // Its shape: the body channel through a resonance near the panel's 12 Hz (within the grid's
    // sixth of an octave), in the verdict and in --json.
    const auto& terms = j["spectral_shape"]["terms"];
    ASSERT_FALSE(terms.empty()) << verdict;
    EXPECT_EQ(terms[0]["shape"], "resonance") << verdict;
    EXPECT_EQ(terms[0]["channel"], "body_acc") << verdict;
    EXPECT_NEAR(std::log2(terms[0]["frequency_Hz"].get<double>() / 12.0), 0.0, 1.0 / 6.0)
        << verdict;
    EXPECT_GT(terms[0]["coefficient"].get<double>(), 0.0) << verdict;
    EXPECT_NE(verdict.find("resonance near"), std::string::npos) << verdict;
  } else if (c.named.empty()) {
    // Nothing missing, no disagreement left (on rig records with the strut's sheet values free,
    // the verdict adds that a load cell's gain cannot be told from them).
    EXPECT_EQ(verdict.rfind("no missing effect found", 0), 0u) << verdict;
    EXPECT_EQ(verdict.find("disagreement remains"), std::string::npos) << verdict;
  }
  if (c.name == "seed_top_mount_stiffening") {
    // datasets/hidden/seed_top_mount_stiffening_truth.yaml: 707 kN/m below δ0 = 5 mm.
    bool found = false;
    for (const auto& p : j["final_parameters"]) {
      if (p["name"] == "top_mount_transition_deflection_m") {
        found = true;
        EXPECT_NEAR(p["value"].get<double>(), 0.005, 0.0005);
      }
      if (p["name"] == "top_mount_small_amplitude_stiffness_N_per_m") {
        EXPECT_NEAR(p["value"].get<double>(), 707e3, 70.7e3);
      }
      // The stick baseline's fit takes the body mass to 341 kg; with the stiffening the mass
      // must come back to the truth's 385.4 kg (a second minimum at 348.5 kg fits the top mount
      // within 10 % all the same but leaves a 2.5 dB gap): effect_selection.h.
      if (p["name"] == "sprung_mass_kg") {
        EXPECT_NEAR(p["value"].get<double>(), 385.4, 0.02 * 385.4);
      }
    }
    EXPECT_TRUE(found) << run.output;
    EXPECT_LT(j["gap_after_dB"].get<double>(), 0.5) << j["verdict"];
  }
}

INSTANTIATE_TEST_SUITE_P(
    Datasets, ShippedHiddenDataset,
    ::testing::Values(
        // Seed 000's own case from the seed's stick model (its values held): from its data-sheet
        // baseline the tolerances let the baseline's top mount take up the stiffer small-amplitude
        // mount (+30 %, 2 standard deviations) and nothing is named, since one smooth-road record
        // shows one amplitude; telling the two apart needs the probabilities and the next test
        // of issues 35 (item 3) and 38. Without tolerances the stiffening is named from the sheet
        // too, with a disagreement the sheet's masses leave.
        ShippedCase{"seed_top_mount_stiffening",
                    "hidden/baselines/passat_stick.yaml",
                    {"top_mount_amplitude_stiffening"}},
        ShippedCase{"top_mount_stiffening_stick_slip",
                    "hidden/top_mount_stiffening_stick_slip_baseline.yaml",
                    {"top_mount_amplitude_stiffening"}},
        ShippedCase{"tyre_damping", "hidden/tyre_damping_baseline.yaml", {"tyre_damping"}},
        ShippedCase{"damper_friction", "hidden/damper_friction_baseline.yaml", {"damper_friction"}},
        ShippedCase{"top_mount_compliance",
                    "hidden/top_mount_compliance_baseline.yaml",
                    {"top_mount_compliance"}},
        ShippedCase{
            "damper_asymmetry", "hidden/damper_asymmetry_baseline.yaml", {"damper_asymmetry"}},
        ShippedCase{
            "damper_digressive", "hidden/damper_digressive_baseline.yaml", {"damper_digressive"}},
        ShippedCase{"bump_stop", "hidden/bump_stop_baseline.yaml", {"bump_stop"}},
        ShippedCase{"tyre_lift_off", "hidden/tyre_lift_off_baseline.yaml", {"tyre_lift_off"}},
        ShippedCase{
            "two_effects", "hidden/two_effects_baseline.yaml", {"bump_stop", "tyre_damping"}},
        ShippedCase{"baseline_only", "hidden/baseline_only_baseline.yaml", {}},
        ShippedCase{"second_body_mode", "hidden/second_body_mode_baseline.yaml", {}, true},
        ShippedCase{"rig_gas_force", "vehicles/passat_b8_front.yaml", {"gas_force"}},
        ShippedCase{
            "rig_stribeck", "vehicles/passat_b8_front.yaml", {"friction_velocity_dependence"}},
        ShippedCase{
            "rig_damper_friction", "hidden/baselines/passat_slip.yaml", {"damper_friction"}},
        ShippedCase{"rig_baseline_only", "vehicles/passat_b8_front.yaml", {}}),
    [](const ::testing::TestParamInfo<ShippedCase>& case_info) { return case_info.param.name; });

// datasets/lab/semi_active_drive.csv: an MR-like damper following its coil current on the road
// (truth.yaml: c = 600 + 1200·ū N·s/m), diagnosed from the passive data sheet (1800 N·s/m).
TEST(ShippedLabDrive, SemiActiveDriveNamesCommandDependence) {
  testing::TempDir dir("ridefit_shipped_drive");
  const auto run = run_cli(
      "diagnose " + dataset("lab/mr_car_passive.yaml") + " " +
      dataset("lab/semi_active_drive.csv") +
      " --effects command_dependence,damper_friction,damper_digressive --json -q --threads 1 -o " +
      (dir.path() / "diagnosis").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto j = nlohmann::json::parse(run.output.substr(run.output.find('{')));
  EXPECT_EQ(j["named"].get<std::vector<std::string>>(),
            std::vector<std::string>{"command_dependence"})
      << j["verdict"];
  int found = 0;
  for (const auto& p : j["final_parameters"]) {
    if (p["name"] == "damping_per_command_Ns_per_m") {
      EXPECT_NEAR(p["value"].get<double>(), 1200.0, 60.0);
      ++found;
    }
    if (p["name"] == "damping_Ns_per_m") {
      EXPECT_NEAR(p["value"].get<double>(), 600.0, 30.0);
      ++found;
    }
  }
  EXPECT_EQ(found, 2) << run.output;
}

}  // namespace
}  // namespace ridefit
