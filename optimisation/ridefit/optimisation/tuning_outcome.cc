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
  outcome.aware = optimise_all(problem,
                               {{FrictionVariant::kStudy, problem.study_limits(),
                                 study_start(study), stage_sink(progress, "")}},
                               searches)
                      .front();
  // The comparisons need an optimum to compare with and to start from; they are independent
  // of each other, so their searches run together.
  if (!outcome.aware.feasible) return outcome;
  std::vector<OptimisationRequest> requests;
  if (study.friction_cost) {
    requests.push_back(
        friction_blind_request(problem, outcome.aware, stage_sink(progress, "friction-blind")));
  }
  if (study.tradeoff) {
    const auto points =
        tradeoff_requests(problem, outcome.aware.best.x, stage_sink(progress, "trade-off"));
    requests.insert(requests.end(), points.begin(), points.end());
  }
  if (requests.empty()) return outcome;
  std::vector<OptimisationRun> runs = optimise_all(problem, requests, searches);
  auto next = runs.begin();
  if (study.friction_cost) {
    outcome.friction = friction_cost_of(problem, outcome.aware, std::move(*next));
    ++next;
  }
  if (study.tradeoff) {
    outcome.tradeoff =
        tradeoff_front(problem, std::vector<OptimisationRun>(std::make_move_iterator(next),
                                                             std::make_move_iterator(runs.end())));
  }
  return outcome;
}

}  // namespace ridefit::optimisation
