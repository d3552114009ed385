#include "ridefit/road/cleat.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/road/road_limits.h"

namespace ridefit::road {
namespace {

constexpr int kSamplesAcrossNarrowest = 40;
// Taller than a tyre's radius is a wall, not a cleat; the bound also keeps h̄ finite.
constexpr double kMaxCleatHeight_m = 1.0;

double sample_step_m(const CleatParameters& p) {
  return std::min(p.length_m, p.tyre_contact_length_m) /
         static_cast<double>(kSamplesAcrossNarrowest);
}

// Where the tyre's contact patch has left the cleat.
double leave_time_s(const CleatParameters& p) {
  return (p.start_distance_m + p.length_m + 0.5 * p.tyre_contact_length_m) / p.speed_m_per_s;
}

double run_duration_s(const CleatParameters& p) {
  return p.duration_s > 0.0 ? p.duration_s : leave_time_s(p) + kCleatSettleTime_s;
}

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
  if (!(height_m <= kMaxCleatHeight_m)) {
    throw InputError(fmt::format("key 'height_m' is {:g} m, expected at most {:g} m", height_m,
                                 kMaxCleatHeight_m));
  }
  require_positive("length_m", length_m);
  require_positive("tyre_contact_length_m", tyre_contact_length_m);
  // 40 samples across the narrower of cleat and patch, over both plus 8 flat samples.
  const double samples = (length_m + tyre_contact_length_m) / sample_step_m(*this) + 9.0;
  if (!(samples <= kMaxRoadSamples)) {
    throw InputError(fmt::format(
        "keys 'length_m' ({:g} m) and 'tyre_contact_length_m' ({:g} m): the cleat is sampled "
        "{} times across the narrower of the two, {:.3g} samples over both, more than {:g}; "
        "the longer may be at most {:g} times the shorter",
        length_m, tyre_contact_length_m, kSamplesAcrossNarrowest, samples, kMaxRoadSamples,
        (kMaxRoadSamples - 9.0) / kSamplesAcrossNarrowest - 1.0));
  }
  check_speed_m_per_s(speed_m_per_s);
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
  const double leave_s = leave_time_s(*this);
  // A relative tolerance, so that a duration computed the same way as leave_s is accepted.
  if (duration_s > 0.0 && !(duration_s >= leave_s * (1.0 - 1e-12))) {
    throw InputError(fmt::format(
        "key 'duration_s' is {:g} s, which ends before the tyre has passed the cleat: at "
        "{:g} m/s its contact patch leaves the cleat at (start_distance_m + length_m + "
        "tyre_contact_length_m/2)/speed = {:g} s; expected duration_s >= {:g} s, or leave it "
        "out for {:g} s more than that",
        duration_s, speed_m_per_s, leave_s, leave_s, kCleatSettleTime_s));
  }
  if (duration_s > 0.0 && duration_s < kMinRoadDuration_s) {
    throw InputError(fmt::format("key 'duration_s' is {:g} s, expected at least {:g} s", duration_s,
                                 kMinRoadDuration_s));
  }
  // The integrator may step at most one sample (max_step_s()) over the whole run.
  const double steps = run_duration_s(*this) * speed_m_per_s / sample_step_m(*this);
  if (!(steps <= kMaxRoadSamples)) {
    throw InputError(fmt::format(
        "keys 'duration_s' and 'start_distance_m': the run lasts {:g} s at {:g} m/s over a cleat "
        "sampled every {:g} m (min(length_m, tyre_contact_length_m)/{}), {:.3g} integrator steps "
        "of one sample, more than {:g}; shorten duration_s or start_distance_m",
        run_duration_s(*this), speed_m_per_s, sample_step_m(*this), kSamplesAcrossNarrowest, steps,
        kMaxRoadSamples));
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
  const double step = sample_step_m(p);
  // Four flat samples on each side: the spline starts and ends at 0 with zero slope.
  const double first = p.start_distance_m - half - 4.0 * step;
  const double last = p.start_distance_m + p.length_m + half + 4.0 * step;
  const auto count = static_cast<std::size_t>(std::ceil((last - first) / step)) + 1;
  std::vector<double> samples(count);
  for (std::size_t k = 0; k < count; ++k) {
    samples[k] = enveloped_cleat_elevation_m(p, first + step * static_cast<double>(k));
  }
  // origin 0: the tyre is at road distance 0 at t = 0; the profile starts at `first`.
  return SpatialProfileRoad(UniformSpline(samples, first, step, 0.0, 0.0), p.speed_m_per_s,
                            run_duration_s(p));
}

}  // namespace ridefit::road
