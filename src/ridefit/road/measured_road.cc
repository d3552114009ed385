#include "ridefit/road/measured_road.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/io/command_column.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/measurement_file.h"
#include "ridefit/road/resample.h"
#include "ridefit/road/road_limits.h"

namespace ridefit::road {
namespace {

constexpr std::size_t kMinimumSamples = 5;  // the B-spline's end-slope estimate needs 5
// Elevations beyond this are no road (and would overflow the spline's arithmetic near 1e308).
constexpr double kMaxElevation_m = 1e4;

}  // namespace

UniformSpline MeasuredRoad::make_signal(std::span<const double> time_s,
                                        std::span<const double> elevation_m) {
  if (time_s.size() != elevation_m.size() || time_s.size() < kMinimumSamples) {
    throw InputError(
        fmt::format("a measured road needs at least {} (time, elevation) samples, "
                    "got {} times and {} elevations",
                    kMinimumSamples, time_s.size(), elevation_m.size()));
  }
  for (std::size_t k = 0; k < time_s.size(); ++k) {
    if (k > 0 && !(time_s[k] > time_s[k - 1])) {
      throw InputError(
          fmt::format("measured road sample {}: time {} s is not greater than the "
                      "previous {} s; time must be strictly increasing",
                      k, time_s[k], time_s[k - 1]));
    }
    if (!(std::abs(elevation_m[k]) <= kMaxElevation_m)) {
      throw InputError(fmt::format(
          "measured road sample {}: elevation {:g} m, expected a finite value within ±{:g} m", k,
          elevation_m[k], kMaxElevation_m));
    }
  }
  const double length_s = time_s.back() - time_s.front();
  if (!(length_s >= kMinRoadDuration_s)) {
    throw InputError(fmt::format(
        "the measured road lasts {:g} s (time {:g} to {:g} s), expected at least {:g} s (one "
        "output sample at 1 kHz); check the time column's unit",
        length_s, time_s.front(), time_s.back(), kMinRoadDuration_s));
  }
  const double samples = resampled_count(time_s);
  if (!(samples <= kMaxRoadSamples) || !std::isfinite(length_s)) {
    throw InputError(fmt::format(
        "the measured road lasts {:g} s (time {:g} to {:g} s) and would be resampled at its "
        "median time step to {:.3g} samples, more than {:g}; give a shorter recording or sample "
        "it more evenly",
        length_s, time_s.front(), time_s.back(), samples, kMaxRoadSamples));
  }
  const UniformSamples uniform = resample_uniform(time_s, elevation_m);
  return UniformSpline(uniform.values, 0.0, uniform.step);
}

MeasuredRoad::MeasuredRoad(std::span<const double> time_s, std::span<const double> elevation_m)
    : signal_(make_signal(time_s, elevation_m)), start_time_s_(time_s.front()) {}

MeasuredRoad::MeasuredRoad(std::span<const double> time_s, std::span<const double> elevation_m,
                           std::span<const double> command, std::string command_unit)
    : MeasuredRoad(time_s, elevation_m) {
  command_unit_ = std::move(command_unit);
  if (command.size() != time_s.size()) {
    throw InputError(
        fmt::format("a measured command needs one value per time sample, got {} for {}",
                    command.size(), time_s.size()));
  }
  for (std::size_t k = 0; k < command.size(); ++k) {
    if (!std::isfinite(command[k])) {
      throw InputError(
          fmt::format("measured command sample {}: {} is not a finite number", k, command[k]));
    }
  }
  command_ = resample_uniform(time_s, command).values;
}

RoadSample MeasuredRoad::at(double time_s) const {
  RoadSample sample{signal_.value(time_s), signal_.derivative(time_s)};
  if (!command_.empty()) {
    const double position =
        std::clamp(time_s / signal_.step(), 0.0, static_cast<double>(command_.size() - 1));
    const auto k = std::min(static_cast<std::size_t>(position), command_.size() - 2);
    const double share = position - static_cast<double>(k);
    sample.command = (1.0 - share) * command_[k] + share * command_[k + 1];
  }
  return sample;
}

MeasuredRoad load_measured_road(const std::filesystem::path& csv_file, const std::string& channel) {
  check_data_file(csv_file,
                  fmt::format("a measurement CSV file with a header row like time[s],{}[mm] (time "
                              "in s or ms, the channel in m or mm) and at least {} data rows",
                              channel, kMinimumSamples));
  const io::CsvTable table = io::read_measurement_table(csv_file);
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
  try {
    if (auto command = io::read_command_column(table, csv_file.string())) {
      return MeasuredRoad(time, road.values, command->values, command->unit);
    }
    return MeasuredRoad(time, road.values);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", csv_file.string(), e.what()));
  }
}

}  // namespace ridefit::road
