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

// ε-constraint sweep: the study optimised once per limit of `study.tradeoff`, from the loosest
// limit to the tightest, each run starting from the previous feasible optimum (`start` for the
// first), so that the front is traced continuously; where a tighter limit's optimum rides
// better than a looser one's (the search tolerance), it is taken for the looser limit too, so
// the front is monotone. Returned in increasing limit. Infeasible points are kept and marked
// (run.feasible), never drawn as part of the front.
std::vector<TradeoffPoint> tradeoff_curve(TuningProblem& problem, const std::vector<double>& start,
                                          const ProgressSink& progress = {});

}  // namespace ridefit::optimisation
