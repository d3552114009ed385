#include "ridefit/road/profile_road.h"

#include <fmt/core.h>

#include <cmath>

#include "ridefit/io/csv_table.h"
#include "ridefit/io/input_error.h"
#include "ridefit/road/resample.h"

namespace ridefit::road {
namespace {

constexpr std::size_t kMinimumPoints = 5;  // the B-spline's end-slope estimate needs 5

const std::vector<double>& length_column(const io::CsvTable& table, const std::string& name) {
  const io::CsvColumn& column = table.column(name);
  if (column.unit != "m") {
    throw InputError(fmt::format("{}: column '{}' is in {}, expected a length (m or mm)",
                                 table.source().string(), name, column.unit));
  }
  return column.values;
}

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
  for (std::size_t k = 1; k < distance_m.size(); ++k) {
    if (!(distance_m[k] > distance_m[k - 1])) {
      throw InputError(
          fmt::format("road profile point {}: distance {} m is not greater than the "
                      "previous {} m; distance must be strictly increasing",
                      k, distance_m[k], distance_m[k - 1]));
    }
  }
  if (!(parameters.speed_m_per_s > 0.0) || !std::isfinite(parameters.speed_m_per_s)) {
    throw InputError(
        fmt::format("key 'speed_m_per_s' is {}, expected a value > 0", parameters.speed_m_per_s));
  }
  const UniformSamples uniform = resample_uniform(distance_m, elevation_m);
  const double start = distance_m.front() + parameters.offset_m;
  const double duration_s = (distance_m.back() - start) / parameters.speed_m_per_s;
  if (!(duration_s > 0.0)) {
    throw InputError(
        fmt::format("key 'offset_m' is {} m, which starts the tyre at or beyond the "
                    "profile's end ({} m after its start)",
                    parameters.offset_m, distance_m.back() - distance_m.front()));
  }
  return SpatialProfileRoad(UniformSpline(uniform.values, uniform.start, uniform.step),
                            parameters.speed_m_per_s, duration_s, distance_m.front(),
                            parameters.offset_m);
}

SpatialProfileRoad load_profile_road(const std::filesystem::path& csv_file,
                                     const ProfileRoadParameters& parameters) {
  const io::CsvTable table = io::CsvTable::read(csv_file);
  const std::vector<double>& distance = length_column(table, "distance");
  const std::vector<double>& elevation = length_column(table, "elevation");
  table.strictly_increasing("distance");
  if (table.rows() < kMinimumPoints) {
    throw InputError(fmt::format("{}: {} data rows, a road profile needs at least {}",
                                 csv_file.string(), table.rows(), kMinimumPoints));
  }
  return make_profile_road(distance, elevation, parameters);
}

}  // namespace ridefit::road
