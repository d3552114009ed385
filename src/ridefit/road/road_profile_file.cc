#include "ridefit/road/road_profile_file.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/measurement_file.h"
#include "ridefit/road/opencrg_file.h"
#include "ridefit/road/road_limits.h"

namespace ridefit::road {
namespace {

bool is_opencrg(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".crg";
}

RoadProfile opencrg_profile(const std::filesystem::path& path, double lateral_offset_m) {
  const CrgGrid grid = read_opencrg(path);
  RoadProfile profile;
  profile.elevation_m = crg_track(grid, lateral_offset_m, path.string());
  profile.distance_m.resize(grid.rows());
  for (std::size_t r = 0; r < grid.rows(); ++r) profile.distance_m[r] = grid.u(r);
  return profile;
}

const std::vector<double>& length_column(const io::CsvTable& table, const std::string& name) {
  const io::CsvColumn& column = table.column(name);
  if (column.unit != "m") {
    throw InputError(fmt::format("{}: column '{}' is in {}, expected a length (m or mm)",
                                 table.source().string(), name, column.unit));
  }
  return column.values;
}

// The road channel of a record over time, over the distance driven at `speed_m_per_s`.
RoadProfile record_profile(const io::CsvTable& table, const RoadProfileSource& source) {
  const std::string file = table.source().string();
  std::string channel = source.channel;
  if (channel.empty())
    channel = !table.has("road") && table.has("road_front") ? "road_front" : "road";
  if (!table.has(channel)) {
    throw InputError(fmt::format(
        "{}: a vehicle record (a time column) without a road channel '{}'; name the column "
        "that holds the road elevation",
        file, channel));
  }
  if (!source.speed_m_per_s) {
    throw MissingDrivingSpeed(fmt::format(
        "{}: a vehicle record over time; its channel '{}' becomes a profile over distance "
        "only with the speed it was driven at",
        file, channel));
  }
  const double speed = *source.speed_m_per_s;
  if (!std::isfinite(speed) || speed <= 0.0 || speed > kMaxSpeed_m_per_s) {
    throw InputError(fmt::format("{}: driving speed {} m/s, expected 0 < speed <= {} m/s", file,
                                 speed, kMaxSpeed_m_per_s));
  }
  const std::vector<double>& time = table.time_s();  // names the row that goes back
  RoadProfile profile;
  profile.elevation_m = length_column(table, channel);
  profile.distance_m.reserve(time.size());
  for (const double t : time) profile.distance_m.push_back(speed * (t - time.front()));
  return profile;
}

// The columns distance and elevation, distance strictly increasing.
RoadProfile profile_over_distance(const io::CsvTable& table) {
  RoadProfile profile{length_column(table, "distance"), length_column(table, "elevation")};
  table.strictly_increasing("distance");  // names the file's row
  return profile;
}

// A CSV or .mat: a profile over distance, or a vehicle record over time.
RoadProfile table_profile(const std::filesystem::path& path, const RoadProfileSource& source) {
  if (source.lateral_offset_m) {
    throw InputError(fmt::format(
        "{}: a lateral offset picks a track of an OpenCRG grid (.crg); a CSV or .mat is one "
        "track already",
        path.string()));
  }
  check_data_file(path,
                  "a road profile CSV (or .mat) file with a header row like "
                  "distance[m],elevation[mm], or a vehicle record like "
                  "time[s],road[mm],body_acc[m/s^2] (lengths in m or mm)");
  const io::CsvTable table = io::read_measurement_table(path);
  if (!table.has("distance") && table.has("time")) return record_profile(table, source);
  if (source.speed_m_per_s || !source.channel.empty()) {
    throw InputError(fmt::format(
        "{}: a profile over distance; a driving speed and a channel apply only to a vehicle "
        "record over time (a time column)",
        path.string()));
  }
  return profile_over_distance(table);
}

}  // namespace

RoadProfile read_profile_csv(const std::filesystem::path& path) {
  check_data_file(path,
                  "a road profile CSV file with a header row like distance[m],elevation[mm] "
                  "(lengths in m or mm)");
  return profile_over_distance(io::read_measurement_table(path));
}

RoadProfile load_road_profile(const std::filesystem::path& path, const RoadProfileSource& source) {
  RoadProfile profile;
  if (is_opencrg(path)) {
    if (source.speed_m_per_s || !source.channel.empty()) {
      throw InputError(fmt::format(
          "{}: an OpenCRG road is over distance; a driving speed and a channel apply only to a "
          "vehicle record over time",
          path.string()));
    }
    profile = opencrg_profile(path, source.lateral_offset_m.value_or(0.0));
  } else {
    profile = table_profile(path, source);
  }
  try {
    check_road_profile(profile, 4);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", path.string(), e.what()));
  }
  return profile;
}

}  // namespace ridefit::road
