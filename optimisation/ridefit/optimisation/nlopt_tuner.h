#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ridefit/optimisation/search_runner.h"
#include "ridefit/optimisation/tuning_problem.h"

namespace ridefit::optimisation {

// One point of the search, in evaluation order (for the convergence figure).
struct SearchStep {
  int start = 0;  // which start (0 = the study's own)
  double objective = 0.0;
  double max_violation = 0.0;  // normalised, 0 when every limit holds
  bool reused = false;
};

// The outcome of one optimisation (all starts).
struct OptimisationRun {
  FrictionVariant variant = FrictionVariant::kStudy;
  std::vector<double> limits;  // the constraint limits it ran with
  Evaluation best;             // best point found (search accuracy): the lowest objective among
                               // feasible points, or the least violation when none is feasible
  Evaluation verified;         // `best` re-evaluated at verification accuracy
  bool feasible = false;       // judged on `verified`
  std::vector<ConstraintMargin> margins;  // of `verified`
  std::string nlopt_result;               // NLopt's return of the start that found `best`
  int evaluations = 0;                    // objective calls, over all starts
  int computed = 0;                       // of which not found in the journal or the cache
  std::vector<SearchStep> history;
};

// Progress lines for stderr ("eval 12 (start 1): objective 0.3181, limits hold").
using ProgressSink = std::function<void(const std::string&)>;

// What one optimisation is asked: the model variant, the constraint limits (they replace the
// study's) and the first start (physical units).
struct OptimisationRequest {
  FrictionVariant variant = FrictionVariant::kStudy;
  std::vector<double> limits;
  std::vector<double> start;
  ProgressSink progress;
  // Evaluations to make at the verified optimum, beside the verification (their results are
  // then known to the problem): what the caller will ask next, computed in parallel.
  std::function<void(TuningProblem& branch, const OptimisationRun& run)> follow_up;
};

// Minimises the study's objective under its constraints with the study's NLopt algorithm, in
// coordinates scaled to [0, 1] per variable (log-scaled ones in ln x), from the request's start
// and, for more starts, from seeded uniform points. Derivative-free throughout: COBYLA
// (constraints natively), BOBYQA (inside AUGLAG when constrained), ISRES (constraints
// natively), DIRECT-L (inside AUGLAG when constrained), MLSL-LDS with BOBYQA as the local method
// (inside AUGLAG when constrained). The search is deterministic (NLopt's generator and the starts
// are seeded), which is what lets a resumed run replay its path from the journal.
//
// Every start of every request is an independent search; `runner` spreads them (threads, or
// ranks), then the best of each request's starts (the first of equals, in start order) is
// verified and, where a limit needs it, polished, again spread. So the runs do not depend on the
// runner. RunError when an evaluation fails (the message names the design and the load case).
std::vector<OptimisationRun> optimise_all(TuningProblem& problem,
                                          const std::vector<OptimisationRequest>& requests,
                                          SearchRunner& runner);

// One optimisation on the threads of the study's evaluation settings.
OptimisationRun optimise(TuningProblem& problem, FrictionVariant variant,
                         const std::vector<double>& limits, const std::vector<double>& start,
                         const ProgressSink& progress = {});

// The study's start values.
std::vector<double> study_start(const TuningStudy& study);

}  // namespace ridefit::optimisation
