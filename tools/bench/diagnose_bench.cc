// `ridefit diagnose`'s engine on the shipped seed case: a 60 s quarter-car record at 500 Hz
// (datasets/hidden/top_mount_stiffening_stick_slip*.csv, the stick/slip Passat) against the whole
// effect library, 2 threads; and on the shipped Stribeck rig tests (two 20 s records at 500 Hz).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "ridefit/fitting/diagnose/diagnosis.h"
#include "ridefit/fitting/diagnose/loop_diagnosis.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/io/quarter_car_file.h"

namespace {

namespace dx = ridefit::fitting::diagnose;

std::filesystem::path dataset(const char* relative) {
  return std::filesystem::path(RIDEFIT_SOURCE_DIR) / "datasets" / relative;
}

void BM_DiagnoseSeedCase60sFullLibrary(benchmark::State& state) {
  const auto model = ridefit::io::load_quarter_car(dataset("vehicles/passat_b8_front.yaml"));
  const dx::DiagnosisData data{
      ridefit::fitting::load_psd_measurement(dataset("hidden/top_mount_stiffening_stick_slip.csv")),
      ridefit::fitting::load_psd_measurement(
          dataset("hidden/top_mount_stiffening_stick_slip_2.csv"))};
  dx::DiagnosisOptions options;
  options.selection.threads = 2;
  std::size_t fits = 0;
  bool named = false;
  for (auto _ : state) {
    const dx::DiagnosisResult r = dx::diagnose({model.make_model()}, data, options);
    fits = 0;
    for (const auto& round : r.rounds) {
      for (const auto& t : round.trials) fits += t.skipped.empty() ? 1 : 0;
    }
    named = r.named == std::vector<std::string>{"top_mount_amplitude_stiffening"};
    benchmark::DoNotOptimize(&r);
  }
  state.counters["effect_fits"] = static_cast<double>(fits);
  state.counters["named_correctly"] = named ? 1.0 : 0.0;
}
BENCHMARK(BM_DiagnoseSeedCase60sFullLibrary)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

void BM_DiagnoseRigLoops20sFullLibrary(benchmark::State& state) {
  const auto model = ridefit::io::load_quarter_car(dataset("vehicles/passat_b8_front.yaml"));
  const dx::LoopDiagnosisData data = dx::split_loops(
      {ridefit::fitting::load_hysteresis_record(dataset("hidden/rig_stribeck.csv")),
       ridefit::fitting::load_hysteresis_record(dataset("hidden/rig_stribeck_2.csv"))});
  dx::DiagnosisModel baseline;
  baseline.kind = dx::DataKind::kStrutLoops;
  baseline.strut = ridefit::fitting::strut_on_rig(model.make_model());
  dx::LoopDiagnosisOptions options;
  options.selection.threads = 2;
  bool named = false;
  for (auto _ : state) {
    const dx::DiagnosisResult r = dx::diagnose_loops(baseline, data, options);
    named = r.named == std::vector<std::string>{"friction_velocity_dependence"};
    benchmark::DoNotOptimize(&r);
  }
  state.counters["named_correctly"] = named ? 1.0 : 0.0;
}
BENCHMARK(BM_DiagnoseRigLoops20sFullLibrary)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
