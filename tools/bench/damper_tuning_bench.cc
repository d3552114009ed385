// Damper tuning with NLopt (COBYLA) on datasets/studies/passat_damper_tuning.yaml: two design
// variables (damping, top-mount stiffness), three load cases of 60 s each, the stick/slip strut
// with Dahl friction simulated by the default ESDIRK, load cases in parallel on every core. Only
// the friction-aware optimisation with its verification (no friction-blind run, no trade-off).
// Target: <= 20 s wall on 2 cores. Counters: evaluations, computed ones, seconds per computed
// evaluation. A second case times the linear half car in the frequency domain.
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

#include "ridefit/optimisation/nlopt_tuner.h"
#include "ridefit/optimisation/tuning_problem.h"

namespace {

using namespace ridefit::optimisation;

void tune(benchmark::State& state, const std::string& study_file) {
  const TuningStudy study = load_tuning_study(std::string(RIDEFIT_SOURCE_DIR) + study_file);
  OptimisationRun run;
  double seconds = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    TuningProblem problem(study);  // a fresh cache: every evaluation is computed
    run = optimise(problem, FrictionVariant::kStudy, problem.study_limits(), study_start(study));
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(&run);  // (on a double, 1.7.1's "+r" constraint can clobber it)
  }
  state.counters["evaluations"] = run.evaluations;
  state.counters["computed"] = run.computed;
  state.counters["s_per_evaluation"] =
      seconds / static_cast<double>(state.iterations()) / (run.computed + 1);  // + verification
  state.counters["objective"] = run.verified.objective;
  state.counters["feasible"] = run.feasible ? 1 : 0;
}

void BM_PassatStickSlipThreeCases60s(benchmark::State& state) {
  tune(state, "/datasets/studies/passat_damper_tuning.yaml");
}
BENCHMARK(BM_PassatStickSlipThreeCases60s)->Unit(benchmark::kSecond)->Iterations(1);

void BM_HalfCarLinearFrequencyDomain(benchmark::State& state) {
  tune(state, "/datasets/studies/seed001_damper_tuning_linear.yaml");
}
BENCHMARK(BM_HalfCarLinearFrequencyDomain)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
