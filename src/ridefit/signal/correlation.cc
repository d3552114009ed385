#include "ridefit/signal/correlation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "ridefit/common/errors.h"

namespace ridefit::signal {
namespace {

void check_finite(std::span<const double> data, const char* what) {
  for (std::size_t i = 0; i < data.size(); ++i) {
    if (!std::isfinite(data[i])) {
      throw InputError(
          fmt::format("correlation: {} {} is {}; every level and value must be a finite number",
                      what, i, data[i]));
    }
  }
}

// Mean of the values observed at exactly `level`.
double mean_at(std::span<const double> levels, std::span<const double> values, double level) {
  double sum = 0.0;
  double count = 0.0;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    if (levels[i] == level) {
      sum += values[i];
      count += 1.0;
    }
  }
  return sum / count;
}

std::optional<double> ratio_minus_one(double high, double low) {
  if (low == 0.0) return std::nullopt;
  return high / low - 1.0;
}

}  // namespace

LinearCorrelation linear_correlation(std::span<const double> levels,
                                     std::span<const double> values) {
  if (levels.size() != values.size()) {
    throw InputError(fmt::format("correlation: {} levels but {} values; give one value per level",
                                 levels.size(), values.size()));
  }
  if (levels.size() < 2) {
    throw InputError(fmt::format(
        "correlation: {} (level, value) pairs; a regression needs at least 2 distinct levels",
        levels.size()));
  }
  check_finite(levels, "level");
  check_finite(values, "value");
  const auto [low, high] = std::minmax_element(levels.begin(), levels.end());
  if (*low == *high) {
    throw InputError(
        fmt::format("correlation: every level is {}; zero variance in the levels leaves the slope "
                    "undefined, give at least 2 distinct levels",
                    *low));
  }

  const auto n = static_cast<double>(levels.size());
  double mean_x = 0.0;
  double mean_y = 0.0;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    mean_x += levels[i];
    mean_y += values[i];
  }
  mean_x /= n;
  mean_y /= n;
  double sxx = 0.0;
  double sxy = 0.0;
  double syy = 0.0;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const double dx = levels[i] - mean_x;
    const double dy = values[i] - mean_y;
    sxx += dx * dx;
    sxy += dx * dy;
    syy += dy * dy;
  }

  LinearCorrelation result;
  result.slope = sxy / sxx;
  result.intercept = mean_y - result.slope * mean_x;
  if (!(sxx > 0.0) || !std::isfinite(sxx) || !std::isfinite(syy) ||
      !std::isfinite(result.intercept)) {
    throw InputError(
        "correlation: the squared deviations of the levels or values overflow or underflow "
        "in double precision; rescale them (e.g. change units)");
  }
  const auto [y_low, y_high] = std::minmax_element(values.begin(), values.end());
  if (*y_low != *y_high && syy > 0.0)
    result.pearson_r = std::clamp(sxy / std::sqrt(sxx * syy), -1.0, 1.0);
  result.lowest_level = *low;
  result.highest_level = *high;
  result.relative_increase =
      ratio_minus_one(mean_at(levels, values, *high), mean_at(levels, values, *low));
  result.fitted_relative_increase = ratio_minus_one(result.intercept + result.slope * *high,
                                                    result.intercept + result.slope * *low);
  return result;
}

}  // namespace ridefit::signal
