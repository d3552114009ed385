// Fits on the public real rig records in ../shared/data/real/ (see its README for sources and
// licences; read from there, never copied): the target is ≤ 30 s per fit (median).
// The models and free parameters are tools/validate-real's:
// - the UTFSM MR damper, 10 mm / 2 Hz: five currents pooled, one command law I^p with the
//   press's damped free play and a command-scaled knee whose force above it grows as |v|^n
//   (13 free), each test weighed by its own spread;
// - the dry-friction damper (BRFD), first half: Dahl + free play + direction-dependent friction
//   and the mass the load cell carries (6 free), from the data sheet
//   datasets/lab/friction_damper_datasheet.yaml;
// - the NEES MR damper random test, first half at every third sample, with its voltage: command
//   law, lag, exponent, knee and the load cell's moving mass (11 free).
// Each starts from the data sheet and the levels read off the records, as `fit hysteresis` does.
//   real_record_fit_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
// Without the records the benchmarks report an error and time nothing.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/fitting/strut_start.h"
#include "ridefit/io/quarter_car_file.h"

namespace {

namespace fs = std::filesystem;
using ridefit::fitting::HysteresisRecord;

const fs::path kRealData = fs::path(RIDEFIT_SOURCE_DIR) / ".." / "shared" / "data" / "real";

ridefit::model::StrutTestParameters<double> data_sheet(
    const char* file, const std::map<std::string, double>& values) {
  const auto model =
      ridefit::io::load_quarter_car(fs::path(RIDEFIT_SOURCE_DIR) / "datasets" / "lab" / file);
  return ridefit::fitting::with_strut_values(ridefit::fitting::strut_on_rig(model.make_model()),
                                             values);
}

// The rows of `r` up to `end_s`.
HysteresisRecord until(const HysteresisRecord& r, double end_s) {
  HysteresisRecord cut = r;
  std::size_t n = 0;
  while (n < r.time_s.size() && r.time_s[n] <= end_s) ++n;
  auto keep = [n](auto& v) {
    if (v.size() > n) v.resize(n);
  };
  keep(cut.time_s);
  keep(cut.displacement_m);
  keep(cut.force_N);
  keep(cut.command);
  keep(cut.velocity_m_per_s);
  return cut;
}

// The NEES file's own columns (t [s], A, D [cm], Y [V], fs, V [cm/s], F [N]), every third row
// (as tools/validate-real converts it).
HysteresisRecord nees_random(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  HysteresisRecord r;
  r.source = file.string();
  r.command_unit = std::string(1, 'V');  // not = "V": GCC 12's -Wrestrict false alarm
  for (long row = 0; std::getline(in, line); ++row) {
    if (row % 3 != 0) continue;
    std::stringstream s(line);
    std::vector<double> c;
    // The sample-rate column (fs) is filled on the first row only.
    for (std::string cell; std::getline(s, cell, ',');) {
      c.push_back(cell.empty() ? 0.0 : std::stod(cell));
    }
    if (c.size() < 7) continue;
    r.time_s.push_back(c[0]);
    r.displacement_m.push_back(0.01 * c[2]);
    r.command.push_back(c[3]);
    r.velocity_m_per_s.push_back(0.01 * c[5]);
    r.force_N.push_back(c[6]);
  }
  return r;
}

void fit(
    benchmark::State& state, const std::vector<HysteresisRecord>& records,
    const ridefit::model::StrutTestParameters<double>& start, std::vector<std::string> free,
    ridefit::fitting::RecordWeighting weighting = ridefit::fitting::RecordWeighting::kNewtons) {
  ridefit::fitting::HysteresisFitOptions options;
  options.free = std::move(free);
  options.record_weighting = weighting;
  for (auto _ : state) {
    const auto result =
        ridefit::fitting::fit_hysteresis_from_file_and_records(records, start, options);
    state.counters["iterations"] = result.iterations;
    state.counters["nrmse_percent"] = result.nrmse_percent;
    state.counters["on_bounds"] = static_cast<double>(result.on_bounds.size());
  }
}

bool have(benchmark::State& state, const fs::path& file) {
  if (fs::exists(file)) return true;
  state.SkipWithError((file.string() + " is not there (the public real records)").c_str());
  return false;
}

const std::vector<std::string> kMrFree = {
    "damping_Ns_per_m",           "coulomb_force_N",
    "dahl_sigma0_N_per_m",        "force_offset_N",
    "gas_stiffness_N_per_m",      "damping_per_command_Ns_per_m",
    "coulomb_force_per_command_N"};

void BM_RealMrSineFiveCurrents10mm(benchmark::State& state) {
  const fs::path file = kRealData / "mr_damper_utfsm_10mm_2hz.csv";
  if (!have(state, file)) return;
  const auto tests = ridefit::fitting::load_hysteresis_tests(file);
  std::vector<std::string> free = kMrFree;
  for (const char* name : {"command_exponent", "free_play_m", "free_play_damping_Ns_per_m",
                           "damper_knee_velocity_m_per_s", "damping_above_knee_Ns_per_m",
                           "damping_above_knee_exponent"}) {
    free.emplace_back(name);
  }
  fit(state, tests,
      data_sheet("mr_strut_passive.yaml", {{"top_mount_stiffness_N_per_m", 1e9},
                                           {"free_play_m", 3e-4},
                                           {"free_play_damping_Ns_per_m", 3e4},
                                           {"damper_knee_velocity_m_per_s", 0.04},
                                           {"damping_above_knee_Ns_per_m", 300.0},
                                           {"damping_above_knee_exponent", 0.5}}),
      free, ridefit::fitting::RecordWeighting::kRelative);
}
BENCHMARK(BM_RealMrSineFiveCurrents10mm)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

void BM_RealFrictionDamperFirstHalf(benchmark::State& state) {
  const fs::path file = kRealData / "friction_damper_brfd_1hz_1in.csv";
  if (!have(state, file)) return;
  const auto whole = ridefit::fitting::load_hysteresis_record(file);
  const double half = whole.time_s.front() + 0.5 * (whole.time_s.back() - whole.time_s.front());
  fit(state, {until(whole, half)},
      data_sheet("friction_damper_datasheet.yaml",
                 {{"free_play_m", 0.004}, {"friction_compression_to_rebound_ratio", 0.85}}),
      {"coulomb_force_N", "dahl_sigma0_N_per_m", "force_offset_N", "free_play_m",
       "friction_compression_to_rebound_ratio", "moving_mass_kg"});
}
BENCHMARK(BM_RealFrictionDamperFirstHalf)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

void BM_RealMrRandomFirstHalf(benchmark::State& state) {
  const fs::path file = kRealData / "mr_damper_ranran_50.csv";
  if (!have(state, file)) return;
  const auto whole = nees_random(file);
  const double half = whole.time_s.front() + 0.5 * (whole.time_s.back() - whole.time_s.front());
  std::vector<std::string> free = kMrFree;
  free.erase(free.begin() + 1);  // the passive friction: the knee carries the 0 V yield
  for (const char* name : {"command_lag_s", "command_exponent", "damper_knee_velocity_m_per_s",
                           "damping_above_knee_Ns_per_m", "moving_mass_kg"}) {
    free.emplace_back(name);
  }
  fit(state, {until(whole, half)},
      data_sheet("mr_strut_passive.yaml", {{"top_mount_stiffness_N_per_m", 1e9},
                                           {"command_lag_s", 0.01},
                                           {"command_exponent", 0.6},
                                           {"damper_knee_velocity_m_per_s", 0.05},
                                           {"damping_above_knee_Ns_per_m", 400.0}}),
      free);
}
BENCHMARK(BM_RealMrRandomFirstHalf)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
