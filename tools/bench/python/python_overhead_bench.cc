// The Python module's overhead on a simulation: the 60 s stick/slip quarter car (the Passat
// corner file as shipped, Fc = 60 N) on the shipped ISO 8608 class A road at 50 km/h, 1 kHz
// output, the default ESDIRK at rtol 1e-5, timed as
//   BM_SimulateQuarterCarCpp     simulate::simulate(car, road, options): the library call that
//                                `ridefit simulate` makes;
//   BM_SimulateQuarterCarPython  ridefit.simulate(model, road) through an embedded interpreter:
//                                the same run plus the argument checks, the JSON summary as a
//                                dict and the channels as NumPy arrays.
// Model and road are read once, outside the timed loops, on both sides. The Python benchmark
// also reports its overhead per call directly (overhead_ms, overhead_pct: the call's time less
// the library call's inside it). Run with
//   build/tools/python_overhead_bench --benchmark_repetitions=5
// and compare the medians: (Python − C++) / C++ is the overhead.
#include <benchmark/benchmark.h>
#include <pybind11/embed.h>

#include <chrono>
#include <memory>
#include <string>

#include "ridefit/io/quarter_car_file.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/simulate/quarter_car_simulation.h"

namespace py = pybind11;

namespace {

const std::string kModel =
    std::string(RIDEFIT_SOURCE_DIR) + "/datasets/vehicles/passat_b8_front.yaml";
const std::string kRoad =
    std::string(RIDEFIT_SOURCE_DIR) + "/datasets/excitations/iso8608_class_a_50kmh.yaml";

void BM_SimulateQuarterCarCpp(benchmark::State& state) {
  const ridefit::model::QuarterCar car = ridefit::io::load_quarter_car(kModel).make_model();
  const auto road = ridefit::road::load_excitation(kRoad);
  const ridefit::simulate::SimulationOptions options;  // 1 kHz, the road's 60 s, ESDIRK 1e-5
  std::size_t samples = 0;
  for (auto _ : state) {
    const auto response = ridefit::simulate::simulate(car, *road, options);
    samples = response.time_s.size();
    benchmark::DoNotOptimize(response.body_acc_m_per_s2.data());
  }
  state.counters["samples"] = static_cast<double>(samples);
}
BENCHMARK(BM_SimulateQuarterCarCpp)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_SimulateQuarterCarPython(benchmark::State& state) {
  py::module_ ridefit = py::module_::import("ridefit");
  const py::object model = ridefit.attr("load_model")(kModel);
  const py::object road = ridefit.attr("load_excitation")(kRoad);
  const py::object simulate = ridefit.attr("simulate");
  std::size_t samples = 0;
  // The call's own time against the library call's inside it (the summary's wall_time_s): the
  // overhead of one call, unaffected by how the machine's load drifts between the benchmarks.
  double call_s = 0.0;
  double library_s = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const py::object result = simulate(model, road);
    call_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    library_s += result.attr("summary")["wall_time_s"].cast<double>();
    samples = py::len(result["body_acc"]);
  }
  state.counters["samples"] = static_cast<double>(samples);
  const double n = static_cast<double>(state.iterations());
  state.counters["overhead_ms"] = 1e3 * (call_s - library_s) / n;
  state.counters["overhead_pct"] = 100.0 * (call_s - library_s) / library_s;
}
BENCHMARK(BM_SimulateQuarterCarPython)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  // The interpreter of the module's build (the package in build/python).
  py::scoped_interpreter interpreter;
  py::module_::import("sys").attr("path").attr("insert")(0, RIDEFIT_PYTHON_PACKAGE_PARENT);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
