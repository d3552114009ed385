#include "ridefit/road/measured_road.h"

#include <fmt/core.h>

#include <vector>

#include "ridefit/io/csv_table.h"
#include "ridefit/io/input_error.h"
#include "ridefit/road/resample.h"

namespace ridefit::road {
namespace {

constexpr std::size_t kMinimumSamples = 5;  // the B-spline's end-slope estimate needs 5

}  // namespace

UniformSpline MeasuredRoad::make_signal(std::span<const double> time_s,
                                        std::span<const double> elevation_m) {
  if (time_s.size() != elevation_m.size() || time_s.size() < kMinimumSamples) {
    throw InputError(
        fmt::format("a measured road needs at least {} (time, elevation) samples, "
                    "got {} times and {} elevations",
                    kMinimumSamples, time_s.size(), elevation_m.size()));
  }
  for (std::size_t k = 1; k < time_s.size(); ++k) {
    if (!(time_s[k] > time_s[k - 1])) {
      throw InputError(
          fmt::format("measured road sample {}: time {} s is not greater than the "
                      "previous {} s; time must be strictly increasing",
                      k, time_s[k], time_s[k - 1]));
    }
  }
  const UniformSamples uniform = resample_uniform(time_s, elevation_m);
  return UniformSpline(uniform.values, 0.0, uniform.step);
}

MeasuredRoad::MeasuredRoad(std::span<const double> time_s, std::span<const double> elevation_m)
    : signal_(make_signal(time_s, elevation_m)), start_time_s_(time_s.front()) {}

RoadSample MeasuredRoad::at(double time_s) const {
  return {signal_.value(time_s), signal_.derivative(time_s)};
}

MeasuredRoad load_measured_road(const std::filesystem::path& csv_file, const std::string& channel) {
  const io::CsvTable table = io::CsvTable::read(csv_file);
  const std::vector<double>& time = table.time_s();
  const io::CsvColumn& road = table.column(channel);
  if (road.unit != "m") {
    throw InputError(fmt::format("{}: column '{}' is in {}, expected a length (m or mm)",
                                 csv_file.string(), channel, road.unit));
  }
  if (table.rows() < kMinimumSamples) {
    throw InputError(fmt::format("{}: {} data rows, a measured road needs at least {}",
                                 csv_file.string(), table.rows(), kMinimumSamples));
  }
  return MeasuredRoad(time, road.values);
}

}  // namespace ridefit::road
