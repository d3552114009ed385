#include "ridefit/optimisation/tuning_report.h"

#include <fmt/core.h>

namespace ridefit::optimisation {
namespace {

void write_optimum(std::ostream& out, const TuningProblem& problem, const OptimisationRun& run,
                   double wall_time_s) {
  const auto& study = problem.study();
  out << fmt::format(
      "{}: {} with {} start(s), NLopt: {}; {} evaluations ({} computed, {} "
      "from the journal or repeated), {:.1f} s\n",
      study.study_file.string(), to_string(study.optimiser.algorithm), study.optimiser.starts,
      run.nlopt_result, run.evaluations, run.computed, run.evaluations - run.computed, wall_time_s);
  out << (run.feasible ? "Optimum (limits hold at the re-evaluated point):\n"
                       : "INFEASIBLE: the search found no design that holds every limit; "
                         "the least violating design:\n");
  if (run.feasible && run.nlopt_result.starts_with("max")) {
    out << "  (the search stopped at its evaluation or time limit: the best design found, "
           "perhaps not converged)\n";
  }
  for (std::size_t v = 0; v < run.best.x.size(); ++v) {
    out << fmt::format("  {:<36} {:>12.6g}   (start {:g}, bounds {:g} … {:g})\n",
                       study.design[v].name, run.best.x[v], study.design[v].start,
                       study.design[v].lower, study.design[v].upper);
  }
  out << fmt::format("  objective {} ({}): {:.6g}\n", study.objective.metric,
                     to_string(study.objective.aggregate), run.verified.objective);
  for (const auto& m : run.margins) {
    out << fmt::format("  {:<52} value {:>10.5g}  margin {:>+10.4g} ({:+.2f} %) {}\n",
                       m.description, m.value, m.margin, 100 * m.relative_margin,
                       !m.holds          ? "VIOLATED"
                       : m.margin >= 0.0 ? "holds"
                                         : "within tolerance");
  }
  for (std::size_t c = 0; c < study.load_cases.size(); ++c) {
    out << fmt::format("  case {:<16} ({}) {} = {:.5g}\n", study.load_cases[c].name,
                       run.verified.frequency_domain[c] ? "frequency domain" : "simulated",
                       study.objective.metric,
                       run.verified.case_values[c][problem.metric_index(study.objective.metric)]);
  }
}

void write_friction_cost(std::ostream& out, const TuningStudy& study, const OptimisationRun& run,
                         const FrictionCost& f) {
  out << "What ignoring friction costs (both optima evaluated with friction):\n";
  for (std::size_t v = 0; v < run.best.x.size(); ++v) {
    out << fmt::format("  {:<36} aware {:>12.6g}   blind {:>12.6g}\n", study.design[v].name,
                       run.best.x[v], f.blind.best.x[v]);
  }
  out << fmt::format(
      "  objective with friction: aware {:.6g}, blind {:.6g} ({:+.2f} %); the blind model "
      "predicted {:.6g}\n",
      run.verified.objective, f.blind_with_friction.objective, f.comfort_loss_percent,
      f.blind.verified.objective);
  if (!f.blind_feasible_with_friction) {
    out << "  and the blind optimum breaks a limit once friction is present:\n";
    for (const auto& m : f.blind_margins_with_friction) {
      if (!m.holds) out << fmt::format("    {} value {:.5g}\n", m.description, m.value);
    }
  }
}

void write_tradeoff(std::ostream& out, const TuningStudy& study,
                    const std::vector<TradeoffPoint>& tradeoff) {
  const auto& c = study.constraints[study.tradeoff->constraint];
  out << fmt::format("Trade-off: {} against the limit on {}\n", study.objective.metric, c.metric);
  for (const auto& p : tradeoff) {
    out << fmt::format("  limit {:>10.5g}  {}", p.limit,
                       p.run.feasible ? fmt::format("objective {:.5g}, achieved {:.5g}",
                                                    p.run.verified.objective, p.achieved)
                                      : std::string("infeasible"));
    for (std::size_t v = 0; v < p.run.best.x.size(); ++v) {
      out << fmt::format("  {}={:.5g}", study.design[v].name, p.run.best.x[v]);
    }
    out << "\n";
  }
}

}  // namespace

void write_tuning_report(std::ostream& out, const TuningProblem& problem,
                         const TuningOutcome& outcome, double wall_time_s) {
  write_optimum(out, problem, outcome.aware, wall_time_s);
  if (outcome.friction) write_friction_cost(out, problem.study(), outcome.aware, *outcome.friction);
  if (!outcome.tradeoff.empty()) write_tradeoff(out, problem.study(), outcome.tradeoff);
}

std::string infeasibility_message(const OptimisationRun& run) {
  std::string violated;
  for (const auto& m : run.margins) {
    if (!m.holds) violated += fmt::format("; {} reaches {:.5g}", m.description, m.value);
  }
  return fmt::format(
      "infeasible: no design within the bounds holds every limit{}; no optimised model was "
      "written",
      violated);
}

}  // namespace ridefit::optimisation
