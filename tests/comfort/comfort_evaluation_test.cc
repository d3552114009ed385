#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ridefit/comfort/comfort_reaction.h"
#include "ridefit/comfort/total_vibration_value.h"
#include "ridefit/common/errors.h"

namespace ridefit::comfort {
namespace {

using R = ComfortReaction;

TEST(ComfortReaction, OverlappingZonesGiveAllLabelsMildestFirst) {
  EXPECT_EQ(comfort_reactions(0.0), std::vector<R>{R::kNotUncomfortable});
  EXPECT_EQ(comfort_reactions(0.3149), std::vector<R>{R::kNotUncomfortable});
  EXPECT_EQ(comfort_reactions(0.315), std::vector<R>{R::kALittleUncomfortable});
  EXPECT_EQ(comfort_reactions(0.4999), std::vector<R>{R::kALittleUncomfortable});
  EXPECT_EQ(comfort_reactions(0.5),
            (std::vector<R>{R::kALittleUncomfortable, R::kFairlyUncomfortable}));
  EXPECT_EQ(comfort_reactions(0.55),
            (std::vector<R>{R::kALittleUncomfortable, R::kFairlyUncomfortable}));
  EXPECT_EQ(comfort_reactions(0.63),
            (std::vector<R>{R::kALittleUncomfortable, R::kFairlyUncomfortable}));
  EXPECT_EQ(comfort_reactions(0.7), std::vector<R>{R::kFairlyUncomfortable});
  EXPECT_EQ(comfort_reactions(0.9), (std::vector<R>{R::kFairlyUncomfortable, R::kUncomfortable}));
  EXPECT_EQ(comfort_reactions(1.1), std::vector<R>{R::kUncomfortable});
  EXPECT_EQ(comfort_reactions(1.3), (std::vector<R>{R::kUncomfortable, R::kVeryUncomfortable}));
  EXPECT_EQ(comfort_reactions(2.0), std::vector<R>{R::kVeryUncomfortable});
  EXPECT_EQ(comfort_reactions(2.2),
            (std::vector<R>{R::kVeryUncomfortable, R::kExtremelyUncomfortable}));
  EXPECT_EQ(comfort_reactions(2.6), std::vector<R>{R::kExtremelyUncomfortable});
  EXPECT_STREQ(to_string(R::kALittleUncomfortable), "a little uncomfortable");
}

TEST(ComfortReaction, EveryValueHasALabel) {
  for (double a = 0.0; a < 5.0; a += 0.001) EXPECT_FALSE(comfort_reactions(a).empty()) << a;
}

TEST(ComfortReaction, InvalidValueIsInputError) {
  EXPECT_THROW(comfort_reactions(-0.1), InputError);
  EXPECT_THROW(comfort_reactions(std::numeric_limits<double>::quiet_NaN()), InputError);
  EXPECT_THROW(comfort_reactions(std::numeric_limits<double>::infinity()), InputError);
}

TEST(ComfortTotalValue, FactorsOfClause8) {
  using enum Axis;
  using L = MeasurementLocation;
  EXPECT_EQ(comfort_axis_factor(L::kSeatSurface, kZ).weighting, Weighting::kWk);
  EXPECT_EQ(comfort_axis_factor(L::kSeatSurface, kX).weighting, Weighting::kWd);
  EXPECT_DOUBLE_EQ(comfort_axis_factor(L::kSeatSurface, kRotationX).k, 0.63);
  EXPECT_DOUBLE_EQ(comfort_axis_factor(L::kSeatSurface, kRotationY).k, 0.40);
  EXPECT_DOUBLE_EQ(comfort_axis_factor(L::kSeatSurface, kRotationZ).k, 0.20);
  EXPECT_EQ(comfort_axis_factor(L::kSeatSurface, kRotationZ).weighting, Weighting::kWe);
  EXPECT_EQ(comfort_axis_factor(L::kSeatBack, kX).weighting, Weighting::kWc);
  EXPECT_DOUBLE_EQ(comfort_axis_factor(L::kSeatBack, kX).k, 0.80);
  EXPECT_DOUBLE_EQ(comfort_axis_factor(L::kSeatBack, kZ).k, 0.40);
  EXPECT_DOUBLE_EQ(comfort_axis_factor(L::kFeet, kY).k, 0.25);
  EXPECT_DOUBLE_EQ(comfort_axis_factor(L::kFeet, kZ).k, 0.40);
  EXPECT_THROW(comfort_axis_factor(L::kFeet, kRotationX), InputError);
}

TEST(ComfortTotalValue, RootSumOfSquaresWithFactors) {
  using enum Axis;
  using L = MeasurementLocation;
  const std::vector<AxisValue> seat = {
      {L::kSeatSurface, kX, 0.3}, {L::kSeatSurface, kY, 0.2}, {L::kSeatSurface, kZ, 0.5}};
  EXPECT_NEAR(total_vibration_value(seat), std::sqrt(0.09 + 0.04 + 0.25), 1e-15);
  const std::vector<AxisValue> with_pitch_and_back = {
      {L::kSeatSurface, kZ, 0.5}, {L::kSeatSurface, kRotationY, 1.0}, {L::kSeatBack, kX, 0.5}};
  EXPECT_NEAR(total_vibration_value(with_pitch_and_back),
              std::sqrt(0.25 + 0.4 * 0.4 + 0.8 * 0.8 * 0.25), 1e-15);
}

TEST(ComfortTotalValue, BadAxesAreInputErrors) {
  using enum Axis;
  using L = MeasurementLocation;
  const std::vector<AxisValue> twice = {{L::kSeatSurface, kZ, 0.5}, {L::kSeatSurface, kZ, 0.4}};
  try {
    total_vibration_value(twice);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("given twice"), std::string::npos) << e.what();
  }
  const std::vector<AxisValue> negative = {{L::kSeatSurface, kZ, -0.5}};
  EXPECT_THROW(total_vibration_value(negative), InputError);
  const std::vector<AxisValue> rotation_at_back = {{L::kSeatBack, kRotationX, 0.5}};
  EXPECT_THROW(total_vibration_value(rotation_at_back), InputError);
}

}  // namespace
}  // namespace ridefit::comfort
