#pragma once

#include <vector>

#include "ridefit/optimisation/nlopt_tuner.h"

namespace ridefit::optimisation {

// One point of the comfort / road-holding front: the best objective with the swept
// constraint's limit at `limit` (the study's other limits unchanged).
struct TradeoffPoint {
  double limit = 0.0;
  double achieved = 0.0;  // the swept metric at the optimum (verified)
  OptimisationRun run;
};

// ε-constraint sweep: the study optimised once per limit of `study.tradeoff`, each from `start`
// (the study's optimum), so that the points are independent searches that run side by side.
// Requests in the order of the study's limits.
std::vector<OptimisationRequest> tradeoff_requests(const TuningProblem& problem,
                                                   const std::vector<double>& start,
                                                   const ProgressSink& progress = {});
// The front from the requests' runs (in their order): where a tighter limit's optimum rides
// better than a looser one's (the search tolerance), it is taken for the looser limit too, so
// the front is monotone. Returned in increasing limit. Infeasible points are kept and marked
// (run.feasible), never drawn as part of the front.
std::vector<TradeoffPoint> tradeoff_front(const TuningProblem& problem,
                                          std::vector<OptimisationRun> runs);
// Both, on the threads of the study's evaluation settings.
std::vector<TradeoffPoint> tradeoff_curve(TuningProblem& problem, const std::vector<double>& start,
                                          const ProgressSink& progress = {});

}  // namespace ridefit::optimisation
