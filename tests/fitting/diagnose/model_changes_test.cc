// What a diagnosis writes into model.yaml: the values it changed, as the report shows them.
#include "ridefit/fitting/diagnose/model_changes.h"

#include <gtest/gtest.h>

#include "support/passat.h"

namespace ridefit::fitting::diagnose {
namespace {

TEST(ModelChanges, ChangedKeysAndTheDamperStateInTheModelFilesWords) {
  const model::QuarterCar before = testing::passat_corner().make_model();
  auto parameters = before.parameters();
  parameters.coulomb_force_N = 61.23456789;
  const model::QuarterCar after(model::DamperState::kSlip, parameters);
  const auto values = changed_model_values(before, after);
  ASSERT_EQ(values.size(), 2u);
  EXPECT_EQ(values[0], (std::pair<std::string, std::string>("damper_state", "slip")));
  EXPECT_EQ(values[1], (std::pair<std::string, std::string>("coulomb_force_N", "61.2346")));
  EXPECT_TRUE(changed_model_values(before, before).empty());
}

TEST(ModelChanges, StrutRigOnlyValuesAreWordsNotKeys) {
  const auto before = model::dahl_strut_on_rig(5e6, 45.0, 1.0, 488000.0, 886.9);
  auto after = before;
  after.damping_Ns_per_m = 900.0;
  after.gas_force_N = 123.456789;
  after.force_offset_N = 2.5;
  const StrutChanges changes = changed_strut_values(before, after);
  ASSERT_EQ(changes.model_values.size(), 1u);
  EXPECT_EQ(changes.model_values[0],
            (std::pair<std::string, std::string>("damping_Ns_per_m", "900")));
  EXPECT_EQ(changes.rig_only, "gas_force_N: 123.457, force_offset_N: 2.5");
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
