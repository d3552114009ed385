#include "ridefit/optimisation/tradeoff_curve.h"

#include <algorithm>
#include <stdexcept>

namespace ridefit::optimisation {

std::vector<TradeoffPoint> tradeoff_curve(TuningProblem& problem, const std::vector<double>& start,
                                          const ProgressSink& progress) {
  const TuningStudy& study = problem.study();
  if (!study.tradeoff) throw std::invalid_argument("tradeoff_curve: the study has no tradeoff");
  const std::size_t swept = study.tradeoff->constraint;
  std::vector<double> limits = study.tradeoff->limits;
  const bool upper = study.constraints[swept].is_upper;
  // Loosest first: a max is loosest when large, a min when small.
  std::sort(limits.begin(), limits.end());
  if (upper) std::reverse(limits.begin(), limits.end());
  std::vector<TradeoffPoint> points;
  std::vector<double> from = start;
  for (double limit : limits) {
    std::vector<double> all = problem.study_limits();
    all[swept] = limit;
    TradeoffPoint p;
    p.limit = limit;
    p.run = optimise(problem, FrictionVariant::kStudy, all, from, progress);
    // The warm start can lead to another local optimum than a start from the study's own
    // optimum (`start`); where that one holds this limit and rides better, it is the point.
    if (from != start) {
      const Evaluation own = problem.evaluate(FrictionVariant::kStudy, Accuracy::kVerify, start);
      if (problem.feasible(own, all) &&
          (!p.run.feasible || own.objective < p.run.verified.objective)) {
        p.run.best = problem.evaluate(FrictionVariant::kStudy, Accuracy::kSearch, start);
        p.run.verified = own;
        p.run.feasible = true;
        p.run.margins = problem.margins(own, all);
        p.run.nlopt_result += ", the study optimum rides better";
      }
    }
    p.achieved = p.run.verified.constraint_values[swept];
    if (p.run.feasible) from = p.run.best.x;
    points.push_back(std::move(p));
  }
  std::sort(points.begin(), points.end(),
            [](const TradeoffPoint& a, const TradeoffPoint& b) { return a.limit < b.limit; });
  return points;
}

}  // namespace ridefit::optimisation
