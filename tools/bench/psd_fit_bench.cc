// PSD fit of 2 free parameters (top-mount stiffness and Coulomb force) of the Passat stick/slip
// quarter car to body and wheel acceleration spectra of 60 s at 1 kHz on ISO 8608 class A at
// 50 km/h (the measurement simulated once with CVODE at rtol 1e-10, outside the timed loop).
//   psd_fit_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "ridefit/fitting/psd_fit.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/road/measured_road.h"
#include "ridefit/simulate/quarter_car_simulation.h"

namespace {

void BM_PsdFit2Parameters60s(benchmark::State& state) {
  const auto file = ridefit::io::load_quarter_car(std::string(RIDEFIT_SOURCE_DIR) +
                                                  "/datasets/vehicles/passat_b8_front.yaml");
  const ridefit::model::QuarterCar truth(ridefit::model::DamperState::kStickSlip, file.parameters);
  ridefit::road::Iso8608RoadParameters r;
  r.random.speed_m_per_s = 50.0 / 3.6;
  r.random.duration_s = 60.0;
  const auto road = ridefit::road::make_iso8608_road(r);
  // The measurement from CVODE at rtol 1e-10, not from the integrator the fit runs.
  ridefit::simulate::SimulationOptions options;
  options.integrator.method = ridefit::simulate::Method::kCvodeBdf;
  options.integrator.relative_tolerance = 1e-10;
  const auto run = ridefit::simulate::simulate(truth, road, options);
  ridefit::fitting::PsdMeasurement m;
  m.time_s = run.time_s;
  m.sample_rate_Hz = 1000.0;
  m.road = std::make_shared<ridefit::road::MeasuredRoad>(run.time_s, run.road_m);
  m.body_acc_m_per_s2 = run.body_acc_m_per_s2;
  m.wheel_acc_m_per_s2 = run.wheel_acc_m_per_s2;
  auto start = file.parameters;
  start.top_mount_stiffness_N_per_m = 600000.0;
  start.coulomb_force_N = 45.0;
  const ridefit::model::QuarterCar car(ridefit::model::DamperState::kStickSlip, start);
  ridefit::fitting::PsdFitOptions fit_options;
  fit_options.free = {"top_mount_stiffness_N_per_m", "coulomb_force_N"};
  fit_options.band_low_Hz = 0.5;
  fit_options.band_high_Hz = 30.0;
  for (auto _ : state) {
    auto fit = ridefit::fitting::fit_psd(m, car, fit_options);
    benchmark::DoNotOptimize(fit.final_cost);
    state.counters["iterations"] = fit.iterations;
    state.counters["k_tm_N_per_mm"] = fit.values[0] / 1000.0;
    state.counters["Fc_N"] = fit.values[1];
  }
}
BENCHMARK(BM_PsdFit2Parameters60s)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
