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
  // Tightest first. A design that holds a tighter limit holds every looser one, so where the
  // search for a looser limit stopped at a worse design (its tolerance), the tighter one is
  // that limit's optimum too: the front is then monotone, as it must be.
  std::sort(points.begin(), points.end(), [upper](const TradeoffPoint& a, const TradeoffPoint& b) {
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
  std::sort(points.begin(), points.end(),
            [](const TradeoffPoint& a, const TradeoffPoint& b) { return a.limit < b.limit; });
  return points;
}

}  // namespace ridefit::optimisation
