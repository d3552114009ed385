// The fit's parameters are rows of the model's tables: a fit's default box lies inside each
// row's plausibility range, so a fitted value is always one the model file accepts.
#include "ridefit/fitting/strut_parameters.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

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
}

}  // namespace
}  // namespace ridefit::fitting
