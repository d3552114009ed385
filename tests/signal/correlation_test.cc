#include "ridefit/signal/correlation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "support/throws_input_error.h"

namespace ridefit::signal {
namespace {

using testing::throws_input_error;

TEST(LinearCorrelation, ExactLineGivesUnitRAndItsSlope) {
  const std::vector<double> x{0.0, 13.0, 40.0, 66.0, 92.0, 119.0};  // seed 000's friction levels
  std::vector<double> y;
  for (double level : x) y.push_back(0.2 + 0.003 * level);
  const LinearCorrelation c = linear_correlation(x, y);
  ASSERT_TRUE(c.pearson_r.has_value());
  EXPECT_NEAR(*c.pearson_r, 1.0, 1e-12);
  EXPECT_NEAR(c.slope, 0.003, 1e-14);
  EXPECT_NEAR(c.intercept, 0.2, 1e-13);
  EXPECT_EQ(c.lowest_level, 0.0);
  EXPECT_EQ(c.highest_level, 119.0);
  // 0.003·119/0.2 = 1.785: +178.5 %, the same from the data and from the line.
  EXPECT_NEAR(*c.relative_increase, 1.785, 1e-12);
  EXPECT_NEAR(*c.fitted_relative_increase, 1.785, 1e-12);

  // A falling line, pairs out of order.
  const std::vector<double> xf{3.0, 1.0, 2.0};
  const std::vector<double> yf{-5.0, -1.0, -3.0};
  const LinearCorrelation f = linear_correlation(xf, yf);
  EXPECT_NEAR(*f.pearson_r, -1.0, 1e-15);
  EXPECT_NEAR(f.slope, -2.0, 1e-15);
  EXPECT_NEAR(f.intercept, 1.0, 1e-15);
}

TEST(LinearCorrelation, KnownDataSetByHand) {
  // x̄ = 1.5, ȳ = 2.75; Sxx = 5, Sxy = 5.5, Syy = 8.75.
  // S = 1.1, intercept = 2.75 − 1.1·1.5 = 1.1, R = 5.5/sqrt(5·8.75) = 0.831521...
  // Data increase 5/1 − 1 = 4; fitted ŷ(3)/ŷ(0) − 1 = 4.4/1.1 − 1 = 3.
  const std::vector<double> x{0.0, 1.0, 2.0, 3.0};
  const std::vector<double> y{1.0, 3.0, 2.0, 5.0};
  const LinearCorrelation c = linear_correlation(x, y);
  EXPECT_NEAR(*c.pearson_r, 5.5 / std::sqrt(43.75), 1e-15);
  EXPECT_NEAR(*c.pearson_r, 0.8315218, 1e-7);
  EXPECT_NEAR(c.slope, 1.1, 1e-15);
  EXPECT_NEAR(c.intercept, 1.1, 1e-15);
  EXPECT_NEAR(*c.relative_increase, 4.0, 1e-15);
  EXPECT_NEAR(*c.fitted_relative_increase, 3.0, 1e-14);
}

TEST(LinearCorrelation, RepetitionsAtALevelAreAveragedForTheIncrease) {
  // Two repetitions at 0 N and at 119 N: level means 1.1 and 1.6, increase 1.6/1.1 − 1.
  // Sxx = 4·59.5², Sxy = 59.5·(0.35 + 0.15 + 0.15 + 0.35) = 59.5, Syy = 0.29.
  const std::vector<double> x{0.0, 119.0, 0.0, 119.0};
  const std::vector<double> y{1.0, 1.5, 1.2, 1.7};
  const LinearCorrelation c = linear_correlation(x, y);
  EXPECT_NEAR(*c.relative_increase, 0.5 / 1.1, 1e-14);
  EXPECT_NEAR(*c.fitted_relative_increase, 0.5 / 1.1, 1e-14);
  EXPECT_NEAR(c.slope, 0.5 / 119.0, 1e-15);
  EXPECT_NEAR(*c.pearson_r, 59.5 / std::sqrt(4.0 * 59.5 * 59.5 * 0.29), 1e-14);
  EXPECT_NEAR(*c.pearson_r, 0.928477, 1e-6);
}

TEST(LinearCorrelation, ConstantValuesHaveNoR) {
  const std::vector<double> x{0.0, 1.0, 2.0};
  const std::vector<double> y{0.7, 0.7, 0.7};
  const LinearCorrelation c = linear_correlation(x, y);
  EXPECT_FALSE(c.pearson_r.has_value());
  EXPECT_NEAR(c.slope, 0.0, 1e-15);
  EXPECT_NEAR(*c.relative_increase, 0.0, 1e-15);

  const std::vector<double> zero{0.0, 0.0, 0.0};
  const LinearCorrelation z = linear_correlation(x, zero);
  EXPECT_FALSE(z.relative_increase.has_value());  // 0/0
  EXPECT_FALSE(z.fitted_relative_increase.has_value());
}

TEST(LinearCorrelation, BadInputThrowsWithAMessageNamingTheProblem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> x{0.0, 1.0, 2.0};
  const std::vector<double> y{1.0, 2.0, 3.0};
  const std::vector<double> y_nan{1.0, 2.0, nan};
  const std::vector<double> x_inf{0.0, std::numeric_limits<double>::infinity(), 2.0};
  const std::vector<double> one{1.0};
  const std::vector<double> flat{4.0, 4.0, 4.0};
  const std::vector<double> two{1.0, 2.0};
  const std::vector<double> huge{0.0, 1e200, 2e200};

  EXPECT_TRUE(throws_input_error([&] { linear_correlation(x, y_nan); }, "value 2 is nan"));
  EXPECT_TRUE(throws_input_error([&] { linear_correlation(x_inf, y); }, "level 1 is inf"));
  EXPECT_TRUE(throws_input_error([&] { linear_correlation(one, one); }, "at least 2"));
  EXPECT_TRUE(throws_input_error([&] { linear_correlation(flat, y); }, "zero variance"));
  EXPECT_TRUE(throws_input_error([&] { linear_correlation(x, two); }, "3 levels but 2 values"));
  EXPECT_TRUE(throws_input_error([&] { linear_correlation(huge, y); }, "overflow"));
}

}  // namespace
}  // namespace ridefit::signal
