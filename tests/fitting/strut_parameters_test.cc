// The fit's parameters are rows of the model's tables: a fit's default box lies inside each
// row's plausibility range, so a fitted value is always one the model file accepts.
#include "ridefit/fitting/strut_parameters.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "support/throws_input_error.h"

namespace ridefit::fitting {
namespace {

TEST(StrutParameters, EveryFitBoxLiesInsideItsRowsRange) {
  std::set<std::string_view> names;
  for (const auto& p : kStrutParameters) {
    SCOPED_TRACE(std::string(p.name()));
    EXPECT_TRUE(names.insert(p.name()).second);
    EXPECT_LT(p.lower, p.upper);
    EXPECT_TRUE(p.row->contains(p.upper));
    // The lower end may be a row's "off" value (0) only where the row allows it.
    EXPECT_TRUE(p.row->contains(p.lower) || (p.lower == 0.0 && p.row->lower == 0.0)) << p.lower;
    EXPECT_EQ(p.in_model_file, model::quarter_car_parameter_index(p.name()).has_value());
  }
  // A gas spring's rate is not negative (force tension positive): a fit must not trade one
  // against the load cell's offset.
  EXPECT_EQ(kStrutParameters[strut_parameter_index("gas_stiffness_N_per_m")].lower, 0.0);
}

TEST(StrutParameters, ValuesByNameAndTheModelFilesShareOfThem) {
  const auto base = model::dahl_strut_on_rig(5e6, 45.0, 1.0, 488000.0, 886.9);
  const auto p = with_strut_values(base, {{"gas_force_N", 12.0}, {"coulomb_force_N", 50.0}});
  EXPECT_EQ(p.gas_force_N, 12.0);
  EXPECT_EQ(p.coulomb_force_N, 50.0);
  const auto unknown = [&] { with_strut_values(base, {{"gas_rate", 1.0}}); };
  EXPECT_TRUE(
      testing::throws_input_error(unknown, "gas_rate: 'gas_rate' is not a strut-test parameter"));
  // The rig-only gas force is no model key.
  const auto values = model_file_values(p, {"gas_force_N", "coulomb_force_N", "force_offset_N"});
  ASSERT_EQ(values.size(), 1u);
  EXPECT_EQ(values[0], (std::pair<std::string, double>("coulomb_force_N", 50.0)));
}

}  // namespace
}  // namespace ridefit::fitting
