#pragma once

#include <ostream>
#include <string>

#include "ridefit/optimisation/tuning_outcome.h"

namespace ridefit::optimisation {

// The tables a person reads after a tuning run: the search, the optimum (or the least violating
// design) with its margins and per-case objective, what ignoring friction costs, the trade-off.
void write_tuning_report(std::ostream& out, const TuningProblem& problem,
                         const TuningOutcome& outcome, double wall_time_s);

// Why a run found no feasible design: every limit the least violating design breaks, and that
// no optimised model was written (the RunError of an infeasible study).
std::string infeasibility_message(const OptimisationRun& run);

}  // namespace ridefit::optimisation
