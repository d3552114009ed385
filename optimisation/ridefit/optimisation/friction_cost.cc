#include "ridefit/optimisation/friction_cost.h"

namespace ridefit::optimisation {

FrictionCost friction_cost(TuningProblem& problem, const OptimisationRun& aware,
                           const ProgressSink& progress) {
  FrictionCost cost;
  cost.blind = optimise(problem, FrictionVariant::kBlind, aware.limits,
                        study_start(problem.study()), progress);
  cost.blind_with_friction =
      problem.evaluate(FrictionVariant::kStudy, Accuracy::kVerify, cost.blind.best.x);
  cost.blind_margins_with_friction = problem.margins(cost.blind_with_friction, aware.limits);
  cost.blind_feasible_with_friction = problem.feasible(cost.blind_with_friction, aware.limits);
  cost.comfort_loss = cost.blind_with_friction.objective - aware.verified.objective;
  cost.comfort_loss_percent = 100.0 * cost.comfort_loss / aware.verified.objective;
  return cost;
}

}  // namespace ridefit::optimisation
