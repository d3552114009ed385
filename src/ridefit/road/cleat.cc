#include "ridefit/road/cleat.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "ridefit/io/input_error.h"

namespace ridefit::road {
namespace {

constexpr int kSamplesAcrossNarrowest = 40;

// ∫_0^s h(σ) dσ for the cleat's own shape, s measured from the cleat's start.
double cleat_integral_m2(const CleatParameters& p, double s) {
  const double c = std::clamp(s, 0.0, p.length_m);
  if (p.shape == CleatShape::kRectangular) return p.height_m * c;
  // Half ellipse: with u = 2s/L − 1, ∫ sqrt(1 − u²) du = (u·sqrt(1 − u²) + asin u)/2.
  const double u = std::clamp(2.0 * c / p.length_m - 1.0, -1.0, 1.0);
  const double g = 0.5 * (u * std::sqrt(1.0 - u * u) + std::asin(u));
  return p.height_m * 0.5 * p.length_m * (g + 0.25 * std::numbers::pi);
}

}  // namespace

CleatShape parse_cleat_shape(const std::string& text) {
  if (text == "semicircular") return CleatShape::kSemicircular;
  if (text == "rectangular") return CleatShape::kRectangular;
  throw InputError(
      fmt::format("cleat shape '{}', expected one of: rectangular, semicircular", text));
}

void CleatParameters::validate() const {
  auto require_positive = [](const char* key, double value) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw InputError(fmt::format("key '{}' is {}, expected a value > 0", key, value));
    }
  };
  require_positive("height_m", height_m);
  require_positive("length_m", length_m);
  require_positive("tyre_contact_length_m", tyre_contact_length_m);
  require_positive("speed_m_per_s", speed_m_per_s);
  // The car starts at rest on flat road: the contact patch must not touch the cleat at t = 0.
  if (!(start_distance_m >= 0.5 * tyre_contact_length_m) || !std::isfinite(start_distance_m)) {
    throw InputError(fmt::format(
        "key 'start_distance_m' is {}, expected at least half the tyre contact length ({} m) so "
        "the tyre starts on flat road",
        start_distance_m, 0.5 * tyre_contact_length_m));
  }
  if (!(duration_s >= 0.0) || !std::isfinite(duration_s)) {
    throw InputError(fmt::format("key 'duration_s' is {}, expected a value > 0", duration_s));
  }
}

double enveloped_cleat_elevation_m(const CleatParameters& p, double distance_m) {
  const double s = distance_m - p.start_distance_m;
  const double half = 0.5 * p.tyre_contact_length_m;
  return (cleat_integral_m2(p, s + half) - cleat_integral_m2(p, s - half)) /
         p.tyre_contact_length_m;
}

SpatialProfileRoad make_cleat_road(const CleatParameters& p) {
  p.validate();
  const double half = 0.5 * p.tyre_contact_length_m;
  const double step =
      std::min(p.length_m, p.tyre_contact_length_m) / static_cast<double>(kSamplesAcrossNarrowest);
  // Four flat samples on each side: the spline starts and ends at 0 with zero slope.
  const double first = p.start_distance_m - half - 4.0 * step;
  const double last = p.start_distance_m + p.length_m + half + 4.0 * step;
  const auto count = static_cast<std::size_t>(std::ceil((last - first) / step)) + 1;
  std::vector<double> samples(count);
  for (std::size_t k = 0; k < count; ++k) {
    samples[k] = enveloped_cleat_elevation_m(p, first + step * static_cast<double>(k));
  }
  const double leave_s = (p.start_distance_m + p.length_m + half) / p.speed_m_per_s;
  const double duration_s = p.duration_s > 0.0 ? p.duration_s : leave_s + kCleatSettleTime_s;
  // origin 0: the tyre is at road distance 0 at t = 0; the profile starts at `first`.
  return SpatialProfileRoad(UniformSpline(samples, first, step, 0.0, 0.0), p.speed_m_per_s,
                            duration_s);
}

}  // namespace ridefit::road
