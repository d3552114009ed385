#pragma once

#include <optional>
#include <span>

namespace ridefit::signal {

// How an objective value y follows a parameter x over a study (seed 000, Section 4.3 and
// Table 3: objective values at several friction levels, each characterised by the Pearson
// correlation coefficient R and the inclination S of the regression line).
struct LinearCorrelation {
  // Pearson's R = Sxy / sqrt(Sxx·Syy) with centred sums; empty when every y is the same
  // (R is 0/0 then: y does not depend on x, and slope is 0).
  std::optional<double> pearson_r;
  double slope = 0.0;          // least-squares S = Sxy/Sxx, [y unit]/[x unit]
  double intercept = 0.0;      // ŷ(x) = intercept + slope·x
  double lowest_level = 0.0;   // min x
  double highest_level = 0.0;  // max x
  // Relative increase from the lowest to the highest level of the data:
  //   ȳ(x_max)/ȳ(x_min) − 1,
  // where ȳ(x) averages the repetitions at that level (0.19 = +19 %). This is the seed's
  // "the addition of maximum friction increases vertical discomfort by 19–71 %": the measured
  // value with the most added friction against the one without. Empty when ȳ(x_min) = 0.
  std::optional<double> relative_increase;
  // The same read off the fitted line, ŷ(x_max)/ŷ(x_min) − 1 = S·(x_max − x_min)/ŷ(x_min):
  // less sensitive to scatter at the two end levels. Empty when ŷ(x_min) = 0.
  std::optional<double> fitted_relative_increase;
};

// Pearson R, least-squares line and relative increase of values y_i observed at parameter
// levels x_i (pairs in any order; a level may repeat, e.g. one pair per repetition).
//
// Throws InputError when the spans differ in length, hold fewer than 2 pairs, hold a
// non-finite number, or all levels are equal (zero variance in x: no slope).
LinearCorrelation linear_correlation(std::span<const double> levels,
                                     std::span<const double> values);

}  // namespace ridefit::signal
