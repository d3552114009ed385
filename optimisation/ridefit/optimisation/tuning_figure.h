#pragma once

#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/optimisation/tuning_outcome.h"

namespace ridefit::optimisation {

// The figure of a tuning run: the search history (objective per evaluation, marked by whether
// every limit held) and, where there is something to compare, the trade-off front with the
// optimum, and the friction-blind optimum evaluated with friction beside it.
io::Figure tuning_figure(const TuningProblem& problem, const TuningOutcome& outcome);

}  // namespace ridefit::optimisation
