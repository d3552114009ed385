#include "ridefit/io/quarter_car_file.h"

#include <gtest/gtest.h>

#include "ridefit/common/errors.h"
#include "support/passat.h"
#include "support/throws_input_error.h"

namespace ridefit::io {
namespace {

TEST(QuarterCarFile, ReadsEveryKeyOfThePassatCorner) {
  const auto file = load_quarter_car(testing::dataset("vehicles/passat_b8_front.yaml"));
  EXPECT_EQ(file.damper_state, model::DamperState::kStickSlip);
  EXPECT_DOUBLE_EQ(file.parameters.sprung_mass_kg, 385.40);
  EXPECT_DOUBLE_EQ(file.parameters.top_mount_stiffness_N_per_m, 488000.0);
  EXPECT_DOUBLE_EQ(file.parameters.dahl_sigma0_N_per_m, 5.0e6);
  EXPECT_DOUBLE_EQ(file.parameters.coulomb_force_N, 60.0);
}

TEST(QuarterCarFile, OverridesAndDamperStateReplaceTheFilesValues) {
  ModelOverrides overrides{{"coulomb_force_N", 12.0}};
  overrides.damper_state = "slip";
  const auto file = load_quarter_car(testing::dataset("vehicles/passat_b8_front.yaml"), overrides);
  EXPECT_EQ(file.damper_state, model::DamperState::kSlip);
  EXPECT_DOUBLE_EQ(file.parameters.coulomb_force_N, 12.0);
}

TEST(QuarterCarFile, OverridesAreValidatedLikeTheFile) {
  const auto path = testing::dataset("vehicles/passat_b8_front.yaml");
  EXPECT_THROW(load_quarter_car(path, {{"coulomb_force_N", -1.0}}), InputError);
  EXPECT_THROW(load_quarter_car(path, {{"dahl_exponent", 0.0}}), InputError);
  try {
    load_quarter_car(path, {{"coulomb_force", 30.0}});
    FAIL() << "an unknown key must be rejected";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("coulomb_force'"), std::string::npos) << e.what();
  }
  // A number's text is checked by the file's own rule, naming where it came from.
  ModelOverrides typed;
  typed.origin = "given on the command line as --set";
  typed.set("coulomb_force_N", "abc");
  EXPECT_TRUE(testing::throws_input_error(
      [&] { load_quarter_car(path, typed); },
      "key 'coulomb_force_N' is 'abc', expected a number (given on the command line as --set "
      "coulomb_force_N=abc)"));
  ModelOverrides state;
  state.damper_state = "stuck";
  try {
    load_quarter_car(path, state);
    FAIL() << "an unknown damper state must be rejected";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("slip, stick, stick_slip"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ridefit::io
