#include "ridefit/optimisation/tradeoff_curve.h"

#include <algorithm>
#include <stdexcept>

namespace ridefit::optimisation {

std::vector<OptimisationRequest> tradeoff_requests(const TuningProblem& problem,
                                                   const std::vector<double>& start,
                                                   const ProgressSink& progress) {
  const TuningStudy& study = problem.study();
  if (!study.tradeoff) throw std::invalid_argument("tradeoff_requests: the study has no tradeoff");
  std::vector<OptimisationRequest> requests;
  for (double limit : study.tradeoff->limits) {
    std::vector<double> all = problem.study_limits();
    all[study.tradeoff->constraint] = limit;
    requests.push_back({FrictionVariant::kStudy, all, start, progress, {}});
  }
  return requests;
}

std::vector<TradeoffPoint> tradeoff_front(const TuningProblem& problem,
                                          std::vector<OptimisationRun> runs) {
  const TuningStudy& study = problem.study();
  const std::size_t swept = study.tradeoff->constraint;
  const bool upper = study.constraints[swept].is_upper;
  std::vector<TradeoffPoint> points;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    TradeoffPoint p;
    p.limit = study.tradeoff->limits.at(i);
    p.run = std::move(runs[i]);
    p.achieved = p.run.verified.constraint_values[swept];
    points.push_back(std::move(p));
  }
  // Tightest first. A design that holds a tighter limit holds every looser one, so where the
  // search for a looser limit stopped at a worse design (its tolerance), the tighter one is
  // that limit's optimum too: the front is then monotone, as it must be.
  std::stable_sort(points.begin(), points.end(),
                   [upper](const TradeoffPoint& a, const TradeoffPoint& b) {
                     return upper ? a.limit < b.limit : a.limit > b.limit;
                   });
  for (std::size_t i = 1; i < points.size(); ++i) {
    const TradeoffPoint& tighter = points[i - 1];
    TradeoffPoint& looser = points[i];
    if (tighter.run.feasible &&
        (!looser.run.feasible || tighter.run.verified.objective < looser.run.verified.objective)) {
      std::vector<double> all = problem.study_limits();
      all[swept] = looser.limit;
      const double limit = looser.limit;
      looser.run = tighter.run;
      looser.limit = limit;
      looser.run.limits = all;
      looser.run.margins = problem.margins(looser.run.verified, all);
      looser.run.feasible = problem.feasible(looser.run.verified, all);
      looser.achieved = tighter.achieved;
    }
  }
  std::stable_sort(
      points.begin(), points.end(),
      [](const TradeoffPoint& a, const TradeoffPoint& b) { return a.limit < b.limit; });
  return points;
}

std::vector<TradeoffPoint> tradeoff_curve(TuningProblem& problem, const std::vector<double>& start,
                                          const ProgressSink& progress) {
  LocalSearchRunner runner(problem.study().evaluation.threads);
  return tradeoff_front(problem,
                        optimise_all(problem, tradeoff_requests(problem, start, progress), runner));
}

}  // namespace ridefit::optimisation
