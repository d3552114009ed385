#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/study/half_car_metrics.h"
#include "ridefit/study/load_case_evaluation.h"

namespace ridefit::study {

// A parametric study of the half car (seed 001's Figures 5–17), read from YAML:
//
//   model: ../vehicles/ajayi_half_car.yaml    # relative to the study file
//   roads:                                     # name: excitation file (relative too)
//     smooth: ../excitations/smooth_road_seed001.yaml
//     gravel: ../excitations/gravel_road_seed001.yaml
//   speeds_km_per_h: [20, 40, 60, 80]          # or speeds_m_per_s; default: each road's own
//   vary:                                      # optional; each entry one axis of the grid
//     - parameter: [front.spring_stiffness_N_per_m, rear.spring_stiffness_N_per_m]
//       name: suspension_stiffness_N_per_m     # column name; default: the first key
//       values: [10000, 16812, 25000]          # or:
//       # range: {from: 10000, to: 40000, count: 7, spacing: linear}   # or log
//   combine: grid                              # grid (default) | zip (axes side by side)
//   method: auto                               # auto | frequency | time
//   time: {output_rate_Hz: 1000, settle_s: 2, duration_s: 60}   # time-domain runs; optional
//   plot: {x: speed_km_per_h, series: road,
//          y: [lower_body_acc_wk_rms_m_per_s2, upper_body_acc_wk_rms_m_per_s2]}
//
// A parameter is any numeric key of the model file by its dotted path (a list sets several
// keys to the same value, e.g. both axles). `method: auto` evaluates in the frequency domain
// (exact, about 2 ms a run) when the car is linear and the road is a random road with a
// spectrum, and simulates otherwise. Every bad entry is an InputError naming the study file and
// its key; the model is loaded with every combination before anything runs, so a value the
// model rejects is reported with its run.
struct SweepAxis {
  std::string name;               // column name
  std::vector<std::string> keys;  // model keys set to the value
  std::vector<double> values;
};

struct SweepPlot {
  std::string x;               // speed_km_per_h or an axis name
  std::string series;          // road, speed_km_per_h, an axis name, or empty
  std::vector<std::string> y;  // metric names (HalfCarMetrics::named())
};

struct HalfCarSweep {
  std::filesystem::path study_file;
  std::filesystem::path model_file;
  std::vector<std::pair<std::string, std::filesystem::path>> roads;
  std::vector<double> speeds_m_per_s;  // empty: each road's own speed
  std::vector<SweepAxis> axes;
  bool zip = false;
  EvaluationMethod method = EvaluationMethod::kAuto;
  double output_rate_Hz = 1000.0;
  double settle_s = 2.0;
  double duration_s = 0.0;  // 0: the road's own
  std::optional<SweepPlot> plot;
};

HalfCarSweep load_half_car_sweep(const std::filesystem::path& study_file);

// One run of the study: a road, a speed and a value per axis.
struct SweepPoint {
  std::size_t road = 0;
  double speed_m_per_s = 0.0;
  std::vector<double> values;  // per axis
};

// Roads outermost, then speeds, then the axes (grid: the last axis fastest; zip: side by side).
std::vector<SweepPoint> expand(const HalfCarSweep& sweep);

struct SweepRow {
  SweepPoint point;
  bool frequency_domain = false;
  HalfCarMetrics metrics;
};

// The study ready to run: every run's car made and checked, every road (a spectrum or a
// generated profile per road and speed) made once. Construction throws InputError for a value
// the model rejects (naming the run), a settle time not below a road's duration, or a road
// without a speed. run(i) evaluates run i alone, so runs may go to threads or to processes.
class PreparedSweep {
 public:
  // `threads` make the cars (0 = every core).
  explicit PreparedSweep(const HalfCarSweep& sweep, unsigned threads = 0);
  PreparedSweep(const PreparedSweep&) = delete;
  PreparedSweep& operator=(const PreparedSweep&) = delete;
  ~PreparedSweep();

  std::size_t runs() const;
  SweepRow run(std::size_t i) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Runs every point on `threads` threads (0 = every core); `progress(done, total)` after each.
std::vector<SweepRow> run_half_car_sweep(
    const HalfCarSweep& sweep, unsigned threads = 0,
    const std::function<void(std::size_t, std::size_t)>& progress = {});

// "N/m" for a name ending in _N_per_m, "m/s^2" for _m_per_s2, … ("1" when none applies), and
// the name without that suffix: a CSV column name[unit].
std::pair<std::string, std::string> split_unit_suffix(const std::string& name);

}  // namespace ridefit::study
