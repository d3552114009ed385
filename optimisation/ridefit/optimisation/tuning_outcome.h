#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ridefit/optimisation/friction_cost.h"
#include "ridefit/optimisation/nlopt_tuner.h"
#include "ridefit/optimisation/tradeoff_curve.h"

namespace ridefit::optimisation {

// Everything a tuning study finds: the optimum and, when the study asks for them, the cost of
// ignoring friction and the comfort / road-holding trade-off (both only beside a feasible
// optimum: they need one to compare with and to start from).
struct TuningOutcome {
  OptimisationRun aware;  // friction-aware where the model has friction
  std::optional<FrictionCost> friction;
  std::vector<TradeoffPoint> tradeoff;
};

// Progress lines with the stage they come from: "" for the optimum, "friction-blind" and
// "trade-off" for the comparisons.
using StageProgress = std::function<void(const std::string& stage, const std::string& line)>;

// Runs the study: the optimum and, where the study asks for them, the friction-blind optimum
// (beside it) and then the trade-off curve (its points side by side). `runner` spreads the searches
// (default: the threads of the study's evaluation settings); the outcome does not depend on it.
// Errors as optimise().
TuningOutcome run_tuning_study(TuningProblem& problem, const StageProgress& progress = {},
                               SearchRunner* runner = nullptr);

}  // namespace ridefit::optimisation
