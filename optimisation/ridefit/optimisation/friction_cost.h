#pragma once

#include "ridefit/optimisation/nlopt_tuner.h"

namespace ridefit::optimisation {

// What tuning blind to friction costs (the seed cites a study where considering friction
// changed the optimal damping): the study is optimised once more on the friction-blind model
// (stick/slip struts as slip struts), and that blind optimum is evaluated with friction, at the
// verification accuracy, beside the friction-aware optimum.
struct FrictionCost {
  OptimisationRun blind;           // optimised without friction; its own objective is what the
                                   // engineer would have expected
  Evaluation blind_with_friction;  // the blind optimum on the real (friction) model
  std::vector<ConstraintMargin> blind_margins_with_friction;
  bool blind_feasible_with_friction = false;
  double comfort_loss = 0.0;          // blind-with-friction objective − aware objective
  double comfort_loss_percent = 0.0;  // of the aware objective
};

// The blind optimisation under `limits` (the aware run's), from the study's start; it does
// not depend on the aware optimum, so it can run beside it.
OptimisationRequest friction_blind_request(const TuningProblem& problem,
                                           const std::vector<double>& limits,
                                           const ProgressSink& progress = {});
// The cost from the blind run (friction_blind_request's, optimised).
FrictionCost friction_cost_of(TuningProblem& problem, const OptimisationRun& aware,
                              OptimisationRun blind);
// Both, on the threads of the study's evaluation settings.
FrictionCost friction_cost(TuningProblem& problem, const OptimisationRun& aware,
                           const ProgressSink& progress = {});

}  // namespace ridefit::optimisation
