#include "ridefit/road/road_profile.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "ridefit/common/errors.h"

namespace ridefit::road {

void check_road_profile(const RoadProfile& profile, std::size_t minimum_samples) {
  const std::vector<double>& x = profile.distance_m;
  const std::vector<double>& y = profile.elevation_m;
  if (x.size() != y.size()) {
    throw InputError(
        fmt::format("road profile: {} distances but {} elevations; every sample needs both",
                    x.size(), y.size()));
  }
  minimum_samples = std::max<std::size_t>(minimum_samples, 2);
  if (x.size() < minimum_samples) {
    throw InputError(
        fmt::format("road profile: {} samples, at least {} are needed", x.size(), minimum_samples));
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
      throw InputError(fmt::format(
          "road profile: sample {} (distance {} m, elevation {} m) is not finite; every value "
          "must be a finite number",
          i, x[i], y[i]));
    }
    if (i > 0 && !(x[i] > x[i - 1])) {
      throw InputError(fmt::format(
          "road profile: sample {} has distance {} m, not greater than sample {}'s {} m; "
          "distance must be strictly increasing",
          i, x[i], i - 1, x[i - 1]));
    }
  }
}

double profile_length_m(const RoadProfile& profile) {
  if (profile.distance_m.empty()) return 0.0;
  return profile.distance_m.back() - profile.distance_m.front();
}

double median_spacing_m(const RoadProfile& profile) {
  const std::vector<double>& x = profile.distance_m;
  if (x.size() < 2) return 0.0;
  std::vector<double> spacing(x.size() - 1);
  for (std::size_t k = 0; k + 1 < x.size(); ++k) spacing[k] = x[k + 1] - x[k];
  const auto middle = spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2);
  std::nth_element(spacing.begin(), middle, spacing.end());
  return *middle;
}

double nominal_spacing_m(const RoadProfile& profile) {
  const double median = median_spacing_m(profile);
  if (profile.distance_m.size() < 2 || !is_uniform(profile, median)) return median;
  return profile_length_m(profile) / static_cast<double>(profile.distance_m.size() - 1);
}

bool is_uniform(const RoadProfile& profile, double spacing_m) {
  const std::vector<double>& x = profile.distance_m;
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    if (std::abs(x[k + 1] - x[k] - spacing_m) > 1e-6 * spacing_m) return false;
  }
  return true;
}

double elevation_at(const RoadProfile& profile, double distance_m) {
  const std::vector<double>& x = profile.distance_m;
  const std::vector<double>& y = profile.elevation_m;
  if (distance_m <= x.front()) return y.front();
  if (distance_m >= x.back()) return y.back();
  const auto upper = std::upper_bound(x.begin(), x.end(), distance_m);
  const auto i = static_cast<std::size_t>(upper - x.begin());  // x[i-1] <= d < x[i]
  const double s = (distance_m - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + s * (y[i] - y[i - 1]);
}

RoadProfile uniform(const RoadProfile& profile, double spacing_m) {
  check_road_profile(profile);
  const double length = profile_length_m(profile);
  if (!std::isfinite(spacing_m) || !(spacing_m > 0.0) || spacing_m > length) {
    throw InputError(fmt::format(
        "road profile: resampling spacing {} m is invalid; expected 0 < spacing <= {} m (the "
        "profile's length)",
        spacing_m, length));
  }
  const double steps = std::floor(length / spacing_m + 1e-9);
  if (steps > 1e8) {
    throw InputError(
        fmt::format("road profile: {} m at {} m spacing is {:.3g} samples, more than 1e8", length,
                    spacing_m, steps));
  }
  const auto count = static_cast<std::size_t>(steps) + 1;
  const std::vector<double>& x = profile.distance_m;
  const std::vector<double>& y = profile.elevation_m;
  RoadProfile out;
  out.distance_m.resize(count);
  out.elevation_m.resize(count);
  std::size_t i = 1;  // x[i-1] <= d <= x[i]
  for (std::size_t k = 0; k < count; ++k) {
    const double d = std::min(x.front() + static_cast<double>(k) * spacing_m, x.back());
    while (i + 1 < x.size() && x[i] < d) ++i;
    const double s = std::clamp((d - x[i - 1]) / (x[i] - x[i - 1]), 0.0, 1.0);
    out.distance_m[k] = d;
    out.elevation_m[k] = y[i - 1] + s * (y[i] - y[i - 1]);
  }
  return out;
}

}  // namespace ridefit::road
