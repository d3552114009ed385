#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "ridefit/road/road_input.h"
#include "ridefit/road/uniform_spline.h"

namespace ridefit::road {

// A road elevation recorded over time (e.g. the `road` channel of a measurement, or a
// shaker's actuator displacement). Time is shifted so that the first sample is at t = 0:
// at(t) is the recording at start_time_s() + t.
//
// Uniformly sampled data is used as is; otherwise it is first resampled by PCHIP at the
// median time step (resample.h). A C2 cubic B-spline (UniformSpline, end slopes estimated
// from the data) gives h and dh/dt; before the first and after the last sample the road
// holds the end elevation.
class MeasuredRoad : public RoadInput {
 public:
  // At least 5 samples with strictly increasing time over at least 1 ms, elevations within
  // ±10 km, at most 2e7 samples after resampling (road_limits.h); else InputError.
  MeasuredRoad(std::span<const double> time_s, std::span<const double> elevation_m);
  // With a controlled damper's command u(t) (A or V) on the same time base, interpolated linearly
  // between the (resampled) samples and held at its ends; RoadSample::command then carries it.
  MeasuredRoad(std::span<const double> time_s, std::span<const double> elevation_m,
               std::span<const double> command, std::string command_unit);

  RoadSample at(double time_s) const override;
  double duration_s() const override { return signal_.end(); }
  // The (resampled) time step.
  double max_step_s() const override { return signal_.step(); }
  bool has_command() const override { return !command_.empty(); }
  std::string command_unit() const override { return command_unit_; }

  // The recording's time of the first sample (at(0)).
  double start_time_s() const { return start_time_s_; }

 private:
  static UniformSpline make_signal(std::span<const double> time_s,
                                   std::span<const double> elevation_m);
  UniformSpline signal_;
  double start_time_s_;
  std::vector<double> command_;  // on the signal's uniform grid; empty without a command
  std::string command_unit_;
};

// The channel `channel` (in m or mm) of a CSV with a strictly increasing `time` column, with the
// damper command when the CSV has a `current` or `voltage` column (io/command_column.h).
MeasuredRoad load_measured_road(const std::filesystem::path& csv_file,
                                const std::string& channel = "road");

}  // namespace ridefit::road
