#include "ridefit/road/profile_road.h"

#include <fmt/core.h>

#include <cmath>
#include <string>

#include "ridefit/common/errors.h"
#include "ridefit/road/resample.h"
#include "ridefit/road/road_limits.h"
#include "ridefit/road/road_profile_file.h"

namespace ridefit::road {
namespace {

constexpr std::size_t kMinimumPoints = 5;  // the B-spline's end-slope estimate needs 5
// Elevations beyond this are no road (and would overflow the spline's arithmetic near 1e308).
constexpr double kMaxElevation_m = 1e4;

}  // namespace

SpatialProfileRoad make_profile_road(std::span<const double> distance_m,
                                     std::span<const double> elevation_m,
                                     const ProfileRoadParameters& parameters) {
  if (distance_m.size() != elevation_m.size() || distance_m.size() < kMinimumPoints) {
    throw InputError(
        fmt::format("a road profile needs at least {} (distance, elevation) points, "
                    "got {} distances and {} elevations",
                    kMinimumPoints, distance_m.size(), elevation_m.size()));
  }
  for (std::size_t k = 0; k < distance_m.size(); ++k) {
    if (k > 0 && !(distance_m[k] > distance_m[k - 1])) {
      throw InputError(
          fmt::format("road profile point {}: distance {} m is not greater than the "
                      "previous {} m; distance must be strictly increasing",
                      k, distance_m[k], distance_m[k - 1]));
    }
    if (!(std::abs(elevation_m[k]) <= kMaxElevation_m)) {
      throw InputError(fmt::format(
          "road profile point {}: elevation {:g} m, expected a finite value within ±{:g} m", k,
          elevation_m[k], kMaxElevation_m));
    }
  }
  check_speed_m_per_s(parameters.speed_m_per_s);
  if (!std::isfinite(parameters.offset_m)) {
    throw InputError(
        fmt::format("key 'offset_m' is {}, expected a finite number", parameters.offset_m));
  }
  const double span_m = distance_m.back() - distance_m.front();
  const double points = resampled_count(distance_m);
  if (!(points <= kMaxRoadSamples) || !std::isfinite(span_m)) {
    throw InputError(fmt::format(
        "the profile spans {:g} m (distance {:g} to {:g} m) and would be resampled at its median "
        "point spacing to {:.3g} points, more than {:g}; give a shorter profile or space its "
        "points more evenly",
        span_m, distance_m.front(), distance_m.back(), points, kMaxRoadSamples));
  }
  const UniformSamples uniform = resample_uniform(distance_m, elevation_m);
  const double start = distance_m.front() + parameters.offset_m;
  const double run_m = distance_m.back() - start;
  const double duration_s = run_m / parameters.speed_m_per_s;
  if (!(duration_s > 0.0)) {
    throw InputError(
        fmt::format("key 'offset_m' is {} m, which starts the tyre at or beyond the "
                    "profile's end ({} m after its start)",
                    parameters.offset_m, span_m));
  }
  if (!(duration_s >= kMinRoadDuration_s)) {
    throw InputError(fmt::format(
        "keys 'speed_m_per_s' and 'offset_m': driving the {:g} m from offset_m = {:g} m to the "
        "end of the profile (which spans {:g} m) at {:g} m/s takes {:g} s, shorter than {:g} s "
        "(one output sample at 1 kHz); use a longer profile, a lower speed or a smaller "
        "offset_m",
        run_m, parameters.offset_m, span_m, parameters.speed_m_per_s, duration_s,
        kMinRoadDuration_s));
  }
  if (!(run_m / uniform.step <= kMaxRoadSamples)) {
    throw InputError(fmt::format(
        "key 'offset_m' is {:g} m: the tyre drives {:g} m to the end of a profile sampled every "
        "{:g} m, {:.3g} integrator steps, more than {:g}; expected offset_m >= {:g} m",
        parameters.offset_m, run_m, uniform.step, run_m / uniform.step, kMaxRoadSamples,
        span_m - kMaxRoadSamples * uniform.step));
  }
  return SpatialProfileRoad(UniformSpline(uniform.values, uniform.start, uniform.step),
                            parameters.speed_m_per_s, duration_s, distance_m.front(),
                            parameters.offset_m);
}

SpatialProfileRoad load_profile_road(const std::filesystem::path& csv_file,
                                     const ProfileRoadParameters& parameters) {
  const RoadProfile profile = read_profile_csv(csv_file);
  if (profile.distance_m.size() < kMinimumPoints) {
    throw InputError(fmt::format("{}: {} data rows, a road profile needs at least {}",
                                 csv_file.string(), profile.distance_m.size(), kMinimumPoints));
  }
  try {
    return make_profile_road(profile.distance_m, profile.elevation_m, parameters);
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.starts_with("key")) throw;  // about a YAML key, not the file
    throw InputError(fmt::format("{}: {}", csv_file.string(), message));
  }
}

}  // namespace ridefit::road
