// io::write_model_with_values: the one writer of model files (fit, diagnose, optimise).
#include "ridefit/io/model_values_file.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "support/temp_dir.h"

namespace ridefit::io {
namespace {

using testing::TempDir;

TEST(ModelValuesFile, NumbersReadBackAsTheSameDoubleAndTheRestOfTheFileStays) {
  TempDir dir("ridefit_model_values");
  const auto model = dir.write(
      "model.yaml", "damper_state: slip\nsprung_mass_kg: 385.4\ndamping_Ns_per_m: 1500\n");
  const auto output = dir.path() / "fitted.yaml";
  write_model_with_values(model, {{"damping_Ns_per_m", 1.0 / 3.0}, {"coulomb_force_N", 878.55}},
                          output, "Fitted by a test");
  // yaml-cpp's own text of a double: 17 significant digits, in the file's order, new keys last.
  EXPECT_EQ(testing::text_of(output),
            "# Fitted by a test\ndamper_state: slip\nsprung_mass_kg: 385.4\ndamping_Ns_per_m: "
            "0.33333333333333331\ncoulomb_force_N: 878.54999999999995\n");
  const YAML::Node written = YAML::LoadFile(output.string());
  EXPECT_EQ(written["damping_Ns_per_m"].as<double>(), 1.0 / 3.0);
  EXPECT_EQ(written["coulomb_force_N"].as<double>(), 878.55);
}

TEST(ModelValuesFile, TextValuesAreWrittenAsGivenAlsoUnderADottedPath) {
  TempDir dir("ridefit_model_values");
  const auto model = dir.write("car.yaml", "front:\n  damping_Ns_per_m: 1500\n");
  const auto output = dir.path() / "out.yaml";
  write_model_with_values(model, {{"front.damping_Ns_per_m", "1234.5"}}, output, "a\n# b");
  EXPECT_EQ(testing::text_of(output), "# a\n# b\nfront:\n  damping_Ns_per_m: 1234.5\n");
}

}  // namespace
}  // namespace ridefit::io
