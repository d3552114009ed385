#include "ridefit/optimisation/tuning_outcome.h"

namespace ridefit::optimisation {
namespace {

ProgressSink stage_sink(const StageProgress& progress, const std::string& stage) {
  if (!progress) return {};
  return [progress, stage](const std::string& line) { progress(stage, line); };
}

}  // namespace

TuningOutcome run_tuning_study(TuningProblem& problem, const StageProgress& progress) {
  TuningOutcome outcome;
  outcome.aware = optimise(problem, FrictionVariant::kStudy, problem.study_limits(),
                           study_start(problem.study()), stage_sink(progress, ""));
  if (problem.study().friction_cost && outcome.aware.feasible) {
    outcome.friction =
        friction_cost(problem, outcome.aware, stage_sink(progress, "friction-blind"));
  }
  if (problem.study().tradeoff && outcome.aware.feasible) {
    outcome.tradeoff =
        tradeoff_curve(problem, outcome.aware.best.x, stage_sink(progress, "trade-off"));
  }
  return outcome;
}

}  // namespace ridefit::optimisation
