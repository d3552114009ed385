#include "ridefit/road/road_profile_file.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
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

}  // namespace

RoadProfile read_profile_csv(const std::filesystem::path& path) {
  check_data_file(path,
                  "a road profile CSV file with a header row like distance[m],elevation[mm] "
                  "(lengths in m or mm)");
  const io::CsvTable table = io::read_measurement_table(path);
  RoadProfile profile{length_column(table, "distance"), length_column(table, "elevation")};
  table.strictly_increasing("distance");  // names the file's row
  return profile;
}

RoadProfile load_road_profile(const std::filesystem::path& path,
                              std::optional<double> lateral_offset_m) {
  RoadProfile profile;
  if (is_opencrg(path)) {
    profile = opencrg_profile(path, lateral_offset_m.value_or(0.0));
  } else {
    if (lateral_offset_m) {
      throw InputError(fmt::format(
          "{}: a lateral offset picks a track of an OpenCRG grid (.crg); a profile CSV is "
          "one track already",
          path.string()));
    }
    profile = read_profile_csv(path);
  }
  try {
    check_road_profile(profile, 4);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", path.string(), e.what()));
  }
  return profile;
}

}  // namespace ridefit::road
