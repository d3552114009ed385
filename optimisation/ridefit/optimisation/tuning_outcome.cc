#include "ridefit/optimisation/tuning_outcome.h"

#include <utility>

namespace ridefit::optimisation {
namespace {

ProgressSink stage_sink(const StageProgress& progress, const std::string& stage) {
  if (!progress) return {};
  return [progress, stage](const std::string& line) { progress(stage, line); };
}

}  // namespace

TuningOutcome run_tuning_study(TuningProblem& problem, const StageProgress& progress,
                               SearchRunner* runner) {
  LocalSearchRunner local(problem.study().evaluation.threads);
  SearchRunner& searches = runner ? *runner : local;
  const TuningStudy& study = problem.study();
  TuningOutcome outcome;
  // The friction-blind optimisation does not depend on the aware optimum: it runs beside it,
  // and is dropped when there is no feasible optimum to compare it with.
  std::vector<OptimisationRequest> requests = {{FrictionVariant::kStudy,
                                                problem.study_limits(),
                                                study_start(study),
                                                stage_sink(progress, ""),
                                                {}}};
  if (study.friction_cost) {
    requests.push_back(friction_blind_request(problem, problem.study_limits(),
                                              stage_sink(progress, "friction-blind")));
  }
  std::vector<OptimisationRun> runs = optimise_all(problem, requests, searches);
  outcome.aware = std::move(runs.front());
  if (!outcome.aware.feasible) return outcome;
  if (study.friction_cost) {
    outcome.friction = friction_cost_of(problem, outcome.aware, std::move(runs[1]));
  }
  // The trade-off points start from the optimum.
  if (study.tradeoff) {
    const auto points =
        tradeoff_requests(problem, outcome.aware.best.x, stage_sink(progress, "trade-off"));
    outcome.tradeoff = tradeoff_front(problem, optimise_all(problem, points, searches));
  }
  return outcome;
}

}  // namespace ridefit::optimisation
