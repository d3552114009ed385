#include "ridefit/optimisation/tuning_figure.h"

#include <fmt/core.h>

#include <string>
#include <utility>

#include "ridefit/study/half_car_sweep.h"

namespace ridefit::optimisation {
namespace {

io::PlotPanel history_panel(const TuningStudy& study, const OptimisationRun& run,
                            const std::string& objective_label) {
  io::PlotPanel history = io::xy_panel("search", "evaluation", objective_label);
  io::PlotSeries feasible{"limits hold", {}, {}, {}, {}, io::SeriesStyle::kPoints};
  io::PlotSeries infeasible{"a limit exceeded", {}, {}, {}, {}, io::SeriesStyle::kPoints};
  for (std::size_t i = 0; i < run.history.size(); ++i) {
    const auto& step = run.history[i];
    auto& s = step.max_violation <= study.optimiser.constraint_tolerance ? feasible : infeasible;
    s.x.push_back(static_cast<double>(i + 1));
    s.y.push_back(step.objective);
  }
  for (auto* s : {&feasible, &infeasible}) {
    if (!s->x.empty()) history.series.push_back(*s);
  }
  history.x_range = std::pair{0.0, static_cast<double>(run.history.size() + 1)};
  return history;
}

// The objective against the swept (else the first) constraint's metric: the trade-off front and
// the optima.
io::PlotPanel front_panel(const TuningProblem& problem, const TuningOutcome& o,
                          const std::string& objective_label) {
  const auto& study = problem.study();
  const std::string metric =
      study.tradeoff
          ? study.constraints[study.tradeoff->constraint].metric
          : (study.constraints.empty() ? study.objective.metric : study.constraints.front().metric);
  const std::size_t index = problem.metric_index(metric);
  const auto& c =
      study.tradeoff ? study.constraints[study.tradeoff->constraint] : study.constraints.front();
  const auto [name, unit] = study::split_unit_suffix(metric);
  io::PlotPanel front = io::xy_panel(std::string(study.tradeoff ? "trade-off" : "optima") +
                                         (study.model_has_friction ? " (with friction)" : ""),
                                     fmt::format("{} [{}]", name, unit), objective_label);
  if (!o.tradeoff.empty()) {
    io::PlotSeries curve{"optimum per limit", {}, {}, {}, {}, io::SeriesStyle::kLinesPoints};
    for (const auto& p : o.tradeoff) {
      if (!p.run.feasible) continue;
      curve.x.push_back(p.achieved);
      curve.y.push_back(p.run.verified.objective);
    }
    if (!curve.x.empty()) front.series.push_back(curve);
  }
  auto point = [&](const std::string& label, const Evaluation& e) {
    const double value = problem.aggregate(e, index, c.aggregate, c.is_upper);
    front.series.push_back({label, {value}, {e.objective}, {}, {}, io::SeriesStyle::kPoints});
  };
  point(study.model_has_friction ? "friction-aware optimum" : "optimum", o.aware.verified);
  if (o.friction) point("friction-blind optimum, with friction", o.friction->blind_with_friction);
  front.key_position = "top right";
  return front;
}

}  // namespace

io::Figure tuning_figure(const TuningProblem& problem, const TuningOutcome& outcome) {
  const auto& study = problem.study();
  const auto [objective, objective_unit] = study::split_unit_suffix(study.objective.metric);
  const std::string objective_label = fmt::format("{} [{}]", objective, objective_unit);
  io::Figure figure;
  figure.title = fmt::format("ridefit optimise {}", study.study_file.filename().string());
  figure.panels.push_back(history_panel(study, outcome.aware, objective_label));
  if (!outcome.tradeoff.empty() || (outcome.friction && !study.constraints.empty())) {
    figure.panels.push_back(front_panel(problem, outcome, objective_label));
  }
  return figure;
}

}  // namespace ridefit::optimisation
