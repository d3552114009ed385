#include "ridefit/optimisation/friction_cost.h"

#include <utility>

namespace ridefit::optimisation {

OptimisationRequest friction_blind_request(const TuningProblem& problem,
                                           const std::vector<double>& limits,
                                           const ProgressSink& progress) {
  return {FrictionVariant::kBlind, limits, study_start(problem.study()), progress,
          // The blind optimum with friction, at the verification accuracy: friction_cost_of's.
          [](TuningProblem& branch, const OptimisationRun& blind) {
            branch.evaluate(FrictionVariant::kStudy, Accuracy::kVerify, blind.best.x);
          }};
}

FrictionCost friction_cost_of(TuningProblem& problem, const OptimisationRun& aware,
                              OptimisationRun blind) {
  FrictionCost cost;
  cost.blind = std::move(blind);
  cost.blind_with_friction =
      problem.evaluate(FrictionVariant::kStudy, Accuracy::kVerify, cost.blind.best.x);
  cost.blind_margins_with_friction = problem.margins(cost.blind_with_friction, aware.limits);
  cost.blind_feasible_with_friction = problem.feasible(cost.blind_with_friction, aware.limits);
  cost.comfort_loss = cost.blind_with_friction.objective - aware.verified.objective;
  cost.comfort_loss_percent = 100.0 * cost.comfort_loss / aware.verified.objective;
  return cost;
}

FrictionCost friction_cost(TuningProblem& problem, const OptimisationRun& aware,
                           const ProgressSink& progress) {
  LocalSearchRunner runner(problem.study().evaluation.threads);
  return friction_cost_of(
      problem, aware,
      optimise_all(problem, {friction_blind_request(problem, aware.limits, progress)}, runner)
          .front());
}

}  // namespace ridefit::optimisation
