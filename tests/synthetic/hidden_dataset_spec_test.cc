// The hidden-dataset spec: defaults and units of a good spec, and bad keys refused by name.
#include "ridefit/synthetic/hidden_dataset_spec.h"

#include <gtest/gtest.h>

#include <string>

#include "support/passat.h"
#include "support/temp_dir.h"
#include "support/throws_input_error.h"

namespace ridefit::synthetic {
namespace {

std::string vehicle(const std::string& name, const std::string& extra = "") {
  return "  - name: " + name +
         "\n    model: " + testing::dataset("hidden/baselines/passat_slip.yaml") +
         "\n    set: {tyre_lift_off: 1}\n    effects: [tyre_lift_off]\n    excitation: " +
         testing::dataset("hidden/roads/iso8608_class_d_50kmh_30s.yaml") + "\n" + extra;
}

std::string rig(const std::string& name, const std::string& extra = "") {
  return "  - name: " + name +
         "\n    kind: strut_rig\n    model: " + testing::dataset("vehicles/passat_b8_front.yaml") +
         "\n    rig: {amplitudes_mm: [3, 1.5], frequencies_Hz: [0.7, 2.3]}\n    duration_s: 4\n" +
         extra;
}

TEST(HiddenDatasetSpec, ReadsDefaultsAndRigMillimetres) {
  testing::TempDir dir("ridefit_hidden_spec");
  const auto file = dir.write("spec.yaml", "datasets:\n" + vehicle("lift") + rig("gas"));
  const auto datasets = read_hidden_spec(file);
  ASSERT_EQ(datasets.size(), 2u);
  const HiddenDataset& v = datasets[0];
  EXPECT_FALSE(v.strut_rig);
  EXPECT_EQ(v.records, 2);
  EXPECT_EQ(v.seed, 1);
  EXPECT_EQ(v.sample_rate_Hz, 500.0);
  EXPECT_EQ(v.duration_s, 0.0);  // the excitation's
  EXPECT_EQ(v.set.at("tyre_lift_off"), 1.0);
  EXPECT_EQ(v.sensor.noise_fraction, 0.005);
  EXPECT_EQ(record_file_name(v, 1), "lift.csv");
  EXPECT_EQ(record_file_name(v, 3), "lift_3.csv");
  const HiddenDataset& r = datasets[1];
  EXPECT_TRUE(r.strut_rig);
  EXPECT_EQ(r.sample_rate_Hz, 1000.0);
  EXPECT_EQ(r.noise_N, 0.6);
  ASSERT_EQ(r.rig_amplitudes_m.size(), 2u);
  EXPECT_DOUBLE_EQ(r.rig_amplitudes_m[1], 0.0015);
  EXPECT_EQ(r.rig_frequencies_Hz[1], 2.3);
}

TEST(HiddenDatasetSpec, RefusesAnUnknownKeyNamingItAndTheFile) {
  testing::TempDir dir("ridefit_hidden_spec");
  const auto file = dir.write("spec.yaml", "datasets:\n" + vehicle("lift", "    colour: red\n"));
  EXPECT_TRUE(testing::throws_input_error([&] { read_hidden_spec(file); }, "colour"));
  EXPECT_TRUE(testing::throws_input_error([&] { read_hidden_spec(file); }, "spec.yaml"));
}

TEST(HiddenDatasetSpec, RefusesAnUnknownEffectListingTheKnownOnes) {
  testing::TempDir dir("ridefit_hidden_spec");
  std::string text = "datasets:\n" + vehicle("lift");
  text.replace(text.find("[tyre_lift_off]"), 15, "[tyre_liftoff]");
  const auto file = dir.write("spec.yaml", text);
  EXPECT_TRUE(testing::throws_input_error([&] { read_hidden_spec(file); },
                                          "unknown effect 'tyre_liftoff'; one of:"));
  EXPECT_TRUE(testing::throws_input_error([&] { read_hidden_spec(file); }, "tyre_lift_off"));
}

TEST(HiddenDatasetSpec, RefusesTwoDatasetsOfOneNameAndARigFrequencyAboveNyquist) {
  testing::TempDir dir("ridefit_hidden_spec");
  const auto twice = dir.write("twice.yaml", "datasets:\n" + vehicle("lift") + rig("lift"));
  EXPECT_TRUE(testing::throws_input_error([&] { read_hidden_spec(twice); },
                                          "dataset name 'lift' is also the name of dataset 1"));
  const auto alias = dir.write("alias.yaml", "datasets:\n" + rig("gas", "    sample_rate_Hz: 4\n"));
  EXPECT_TRUE(testing::throws_input_error([&] { read_hidden_spec(alias); },
                                          "2.3 Hz is at or above the Nyquist frequency"));
}

}  // namespace
}  // namespace ridefit::synthetic
